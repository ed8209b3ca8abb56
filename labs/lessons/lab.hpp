#pragma once
// The frame every lab shares: numbered, explained steps (pausing between them with --step),
// tables (printed, and saved as CSV files), and the closing comparison of hand-written methods with GSL.

#include <Eigen/Core>
#include <ostream>
#include <string>
#include <vector>

#include <streambuf>
#include <utility>

#include "output/lab_report.hpp"
#include "output/step_pause.hpp"
#include "output/table.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

class LabSession {
 public:
  // Tables are also saved as CSV files in `folder` (created on first use); finish() writes the
  // whole session as FOLDER/report.html.
  LabSession(std::ostream& out, bool step, std::string folder, std::string title = "", std::string summary = "");

  // Starts the next step: pauses first (with --step, after step 1), then prints its title and
  // explanation. Returns false, printing nothing, once the user has stopped with q: the lab then
  // returns at once, and every later begin_step returns false without asking again.
  [[nodiscard]] bool begin_step(const std::string& title, const std::string& explanation);
  // Whether the user stopped the lab with q at a pause.
  bool stopped() const { return pause_.stopped(); }
  // A paragraph, wrapped to 96 columns and indented.
  void say(const std::string& paragraph);
  // Prints the table and saves it as FOLDER/stepK-NAME.csv.
  void show(const Table& table, const std::string& name);
  // A figure the lab has written (SVG or PNG): named in the output, embedded in the report.
  void figure(const std::string& path, const std::string& caption);
  // A traced solve the report lets the reader step through (LabReport::add_stepper): the tracer's
  // records and printed lines, with `extra` members (gepp's "start"); placed after the output so far.
  void stepper(const std::string& kind, const std::string& caption, const TraceOutput& tracer,
               nlohmann::ordered_json extra = nlohmann::ordered_json::object());
  // Writes FOLDER/report.html (whole or not at all) and returns its path.
  std::string finish();

  // Free-form output; it goes to the terminal and, as preformatted text, into the report.
  std::ostream& out() { return tee_; }
  const std::string& folder() const { return folder_; }
  int steps_taken() const { return step_number_; }
  const LabReport& report() const { return report_; }

 private:
  // A stream buffer that writes to the terminal's buffer and keeps a copy for the report.
  class TeeBuffer : public std::streambuf {
   public:
    explicit TeeBuffer(std::streambuf* terminal) : terminal_(terminal) {}
    std::string take() { return std::exchange(copy_, std::string()); }

   protected:
    int overflow(int c) override;
    std::streamsize xsputn(const char* text, std::streamsize count) override;
    int sync() override { return terminal_->pubsync(); }

   private:
    std::streambuf* terminal_;
    std::string copy_;
  };

  // Moves free-form output written since the last structured item into the report.
  void flush_free_text();

  std::ostream& out_;
  TeeBuffer tee_buffer_;
  std::ostream tee_;
  StepPause pause_;
  std::string folder_;
  int step_number_ = 0;
  LabReport report_;
};

struct Lab {
  std::string name;
  std::string summary;
  int (*run)(LabSession&);  // returns an exit code
};

const std::vector<Lab>& all_labs();

// The closing table of a linear lab: each method's answer, relative residual, forward error and
// median time on A x = b.
Table linear_comparison_table(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& exact,
                              const std::vector<std::string>& methods);

int run_gauss_lab(LabSession& session);
int run_seidel_lab(LabSession& session);
int run_inverse2x2_lab(LabSession& session);
int run_newton_lab(LabSession& session);
int run_jansen_lab(LabSession& session);
int run_jansen_sequential_lab(LabSession& session);
int run_beest_lab(LabSession& session);
int run_mustang_lab(LabSession& session);
int run_fit_lab(LabSession& session);
int run_exercises_lab(LabSession& session);
int run_robustness_lab(LabSession& session);
int run_linkage_lab(LabSession& session);

}  // namespace numlab::cli
