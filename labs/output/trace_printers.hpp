#pragma once
// Trace observers for the hand-written methods: readable text on a stream, or JSON records
// collected for the "trace" array. With --step they pause after each printed record and return the
// user's answer to the stepper (StepControl::stop at q ends its run).

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "output/step_pause.hpp"

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

namespace numlab::cli {

// What every tracer holds: the records collected (for JSON's "trace"), where text goes as each
// record comes (nullptr: nowhere), and the pause after each printed record (--step; nullptr: none).
class TraceOutput {
 public:
  TraceOutput(std::ostream* text_out, StepPause* pause)
      : text_out_(text_out), pause_(pause), waited_at_start_(pause ? pause->seconds_waited() : 0.0) {}
  const nlohmann::ordered_json& records() const { return records_; }
  // The text printed for each record (one entry per record, lines joined by '\n'), and the column
  // header printed before the first (empty when there is none): what a lab report's stepper shows.
  const std::vector<std::string>& lines() const { return lines_; }
  const std::string& header() const { return header_; }

 protected:
  // After the user stopped: nothing more is recorded or printed, and the stepper is told to stop.
  bool stopped() const { return pause_ != nullptr && pause_->stopped(); }
  // The pause after a printed record, and the user's answer (proceed without a pause).
  StepControl pause_after_record() const { return pause_ != nullptr ? pause_->after_step() : StepControl::proceed; }
  // Seconds paused at --step since this tracer was made: taken off the times it prints.
  double paused_since_start() const { return pause_ != nullptr ? pause_->seconds_waited() - waited_at_start_ : 0.0; }
  // Keeps `text` as the record's printed text and prints it (with the header first, once) when
  // text goes somewhere; then pauses as after_record. `header` ends with '\n' or is empty.
  StepControl print_record(const std::string& header, const std::string& text);
  std::ostream* text_out_;
  StepPause* pause_;
  double waited_at_start_;
  bool header_printed_ = false;
  nlohmann::ordered_json records_ = nlohmann::ordered_json::array();
  std::vector<std::string> lines_;
  std::string header_;
};

// Matrices larger than this are summarised in traces rather than printed whole.
constexpr int max_traced_matrix_size = 12;

// Seed 001's verbose mode, made readable: the augmented matrix [A | b] after each row swap and
// each elimination, then each back-substituted value (all indices 1-based).
class EliminationTracer : public linalg::GaussElimination<Eigen::Dynamic>::Observer, public TraceOutput {
 public:
  using TraceOutput::TraceOutput;
  StepControl on_step(const linalg::GaussElimination<Eigen::Dynamic>& state,
                      const linalg::EliminationRecord& record) override;
};

// One row per sweep: k, ||dx||_inf, ||b - A x||_inf of the original system.
class SweepTracer : public linalg::GaussSeidel<Eigen::Dynamic>::Observer, public TraceOutput {
 public:
  using TraceOutput::TraceOutput;
  StepControl on_step(const linalg::GaussSeidel<Eigen::Dynamic>& state, const linalg::SweepRecord& record) override;
};

// The 2x2 closed form in three records: det A = a d - b c with kappa_2(A) (and the verdict singular),
// then A^-1 = (1/det A) [d -b; -c a], then x = A^-1 b.
class ClosedFormTracer : public linalg::ClosedForm2x2::Observer, public TraceOutput {
 public:
  using TraceOutput::TraceOutput;
  StepControl on_step(const linalg::ClosedForm2x2& state, const linalg::ClosedFormRecord& record) override;
};

// Newton on a DynamicSystem with its linear method chosen at run time (solve nonlinear --method newton).
using DynamicNewton = nonlinear::Newton<nonlinear::DynamicReference, nonlinear::RuntimeLinearStep>;

// Every stepper that sends NewtonRecords, behind one interface: Newton, the dogleg, GSL's multiroot
// adapter and sequential Newton. Whoever prints or keeps the records implements on_record() once; `block` is
// sequential Newton's block (an index), -1 for the others.
class NewtonTraceObserver : public DynamicNewton::Observer,
                            public nonlinear::Dogleg::Observer,
                            public nonlinear::GslMultiroot::Observer,
                            public nonlinear::SequentialNewton::Observer {
 public:
  virtual StepControl on_record(const nonlinear::NewtonRecord& record, int block) = 0;
  StepControl on_step(const DynamicNewton&, const nonlinear::NewtonRecord& record) override {
    return on_record(record, -1);
  }
  StepControl on_step(const nonlinear::Dogleg&, const nonlinear::NewtonRecord& record) override {
    return on_record(record, -1);
  }
  StepControl on_step(const nonlinear::GslMultiroot&, const nonlinear::NewtonRecord& record) override {
    return on_record(record, -1);
  }
  StepControl on_step(const nonlinear::SequentialNewton&, const nonlinear::SequentialRecord& record) override {
    return on_record(record.newton, record.block);
  }
};

// One row per Newton iteration: k, ||f||_inf, ||f||_2, ||dx||_inf, the inner linear solve's status
// and iteration count (pivot columns for GEPP, sweeps for Gauss-Seidel), the damping factor and
// the time since the start; for sequential Newton, the block (1-based) first.
class NewtonTracer : public NewtonTraceObserver, public TraceOutput {
 public:
  using TraceOutput::TraceOutput;
  StepControl on_record(const nonlinear::NewtonRecord& record, int block) override;
};

// Prints [M | c] with aligned columns, each line indented.
void print_augmented(std::ostream& out, const Eigen::MatrixXd& M, const Eigen::VectorXd& c);

}  // namespace numlab::cli
