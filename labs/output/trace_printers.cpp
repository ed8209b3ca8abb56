#include "output/trace_printers.hpp"

#include <fmt/format.h>

#include <sstream>

namespace numlab::cli {

namespace {

nlohmann::ordered_json rows_of(const Eigen::MatrixXd& M, const Eigen::VectorXd& c) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index j = 0; j < M.cols(); ++j) row.push_back(M(i, j));
    row.push_back(c(i));
    rows.push_back(row);
  }
  return rows;
}

std::string describe(const linalg::EliminationRecord& record, bool last_column) {
  const int k = record.column + 1;
  switch (record.event) {
    case linalg::EliminationEvent::row_swap:
      return fmt::format("column {}: pivot search picks row {} (|pivot| = {:.4g}); swap rows {} and {}", k,
                         record.other_row + 1, std::abs(record.value), k, record.other_row + 1);
    case linalg::EliminationEvent::elimination:
      if (last_column) return fmt::format("column {}: pivot {:.4g}; no rows below, elimination complete", k, record.value);
      return fmt::format("column {}: pivot {:.4g} in row {}; rows below minus l_i{} * row {} (l_i{} = a_i{} / {:.4g})", k,
                         record.value, k, k, k, k, k, record.value);
    case linalg::EliminationEvent::back_substitution:
      return fmt::format("back substitution: x{} = {:.10g}", k, record.value);
  }
  return "";
}

}  // namespace

StepControl TraceOutput::print_record(const std::string& header, const std::string& text) {
  if (header_.empty()) header_ = header;
  lines_.push_back(text);
  if (text_out_ == nullptr) return StepControl::proceed;
  if (!header_printed_) *text_out_ << header;
  header_printed_ = true;
  *text_out_ << text << '\n';
  return pause_after_record();
}

void print_augmented(std::ostream& out, const Eigen::MatrixXd& M, const Eigen::VectorXd& c) {
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    std::string line = "    ";
    for (Eigen::Index j = 0; j < M.cols(); ++j) line += fmt::format("{:>11.4g}", M(i, j));
    line += fmt::format("  |{:>11.4g}", c(i));
    out << line << '\n';
  }
}

StepControl EliminationTracer::on_step(const linalg::GaussElimination<Eigen::Dynamic>& state,
                                       const linalg::EliminationRecord& record) {
  if (stopped()) return StepControl::stop;
  const bool show_matrix = record.event != linalg::EliminationEvent::back_substitution &&
                           state.size() <= max_traced_matrix_size;
  static const char* names[] = {"row_swap", "elimination", "back_substitution"};
  nlohmann::ordered_json entry = {{"event", names[static_cast<int>(record.event)]}, {"column", record.column + 1}};
  if (record.event == linalg::EliminationEvent::row_swap) entry["swapped_with_row"] = record.other_row + 1;
  if (record.event == linalg::EliminationEvent::back_substitution) {
    entry["value"] = record.value;
  } else {
    entry["pivot"] = record.value;
  }
  if (show_matrix) entry["augmented"] = rows_of(state.reduced_matrix(), state.reduced_rhs());
  records_.push_back(entry);
  std::ostringstream text;
  text << describe(record, record.column + 1 == state.size());
  if (show_matrix) {
    text << '\n';
    print_augmented(text, state.reduced_matrix(), state.reduced_rhs());
  }
  std::string printed = text.str();
  if (printed.ends_with('\n')) printed.pop_back();
  return print_record("", printed);
}

StepControl ClosedFormTracer::on_step(const linalg::ClosedForm2x2& state, const linalg::ClosedFormRecord& record) {
  if (stopped()) return StepControl::stop;
  const Eigen::Matrix2d& A = state.matrix();
  const Eigen::Vector2d& b = state.rhs();
  const bool singular = state.status() == Status::singular;
  // 1. The determinant, judged by the scale of A (kappa_2).
  records_.push_back({{"event", "determinant"},
                      {"augmented", {{A(0, 0), A(0, 1), b(0)}, {A(1, 0), A(1, 1), b(1)}}},
                      {"determinant", record.determinant},
                      {"condition_number", record.condition_number}});
  std::string text = fmt::format("det A = a d - b c = {:.6g} * {:.6g} - {:.6g} * {:.6g} = {:.6g}; kappa_2(A) = {:.4g}",
                                 A(0, 0), A(1, 1), A(0, 1), A(1, 0), record.determinant, record.condition_number);
  if (singular) text += "; singular to working precision (kappa_2 >= 1/eps): no inverse";
  const StepControl control = print_record("", text);
  if (control == StepControl::stop || singular) return control;
  // 2. The inverse: the adjugate over the determinant.
  const Eigen::Matrix2d inverse = linalg::inverse2x2(A).inverse;
  records_.push_back({{"event", "inverse"}, {"inverse", {{inverse(0, 0), inverse(0, 1)}, {inverse(1, 0), inverse(1, 1)}}}});
  const std::string matrix_lines = fmt::format("    {:>11.4g}{:>11.4g}\n    {:>11.4g}{:>11.4g}", inverse(0, 0),
                                               inverse(0, 1), inverse(1, 0), inverse(1, 1));
  if (print_record("", fmt::format("A^-1 = (1 / det A) [d -b; -c a] =\n{}", matrix_lines)) == StepControl::stop) {
    return StepControl::stop;
  }
  // 3. The solution.
  records_.push_back({{"event", "solution"}, {"x", {state.x()(0), state.x()(1)}}});
  return print_record("", fmt::format("x = A^-1 b = ({:.10g}, {:.10g})", state.x()(0), state.x()(1)));
}

StepControl SweepTracer::on_step(const linalg::GaussSeidel<Eigen::Dynamic>& state, const linalg::SweepRecord& record) {
  if (stopped()) return StepControl::stop;
  nlohmann::ordered_json entry = {{"sweep", record.sweep}, {"step_inf", record.step_norm},
                                  {"residual_inf", record.residual_norm}};
  // The iterate after the sweep, for systems small enough to print (as the augmented matrix of GEPP's).
  if (state.x().size() <= max_traced_matrix_size) entry["x"] = std::vector<double>(state.x().begin(), state.x().end());
  records_.push_back(entry);
  return print_record(fmt::format("  {:>6}  {:>12}  {:>16}\n", "sweep", "||dx||_inf", "||b - A x||_inf"),
                      fmt::format("  {:>6}  {:>12.4e}  {:>16.4e}", record.sweep, record.step_norm, record.residual_norm));
}

StepControl NewtonTracer::on_record(const nonlinear::NewtonRecord& record, int block) {
  if (stopped()) return StepControl::stop;
  const bool has_linear_solve = record.linear_iterations != nonlinear::NewtonRecord::no_linear_solve;
  const bool sequential = block >= 0;
  nlohmann::ordered_json entry = nlohmann::ordered_json::object();
  if (sequential) entry["block"] = block + 1;
  entry["iteration"] = record.iteration;
  entry["residual_inf"] = record.residual_norm;
  entry["residual_2"] = record.residual_2norm;
  entry["step_inf"] = record.step_norm;
  if (has_linear_solve) {
    entry["linear_status"] = std::string(to_string(record.linear_status));
    entry["linear_iterations"] = record.linear_iterations;
  }
  entry["damping"] = record.damping;
  const bool chord = record.jacobian_refactored != nonlinear::NewtonRecord::every_iteration;
  if (chord) entry["jacobian"] = record.jacobian_refactored == 1 ? "refactored" : "reused";
  const double time_s = record.elapsed_s - paused_since_start();
  entry["time_s"] = time_s;
  records_.push_back(entry);
  const std::string header =
      (sequential ? fmt::format("  {:>5}", "block") : std::string()) +
      fmt::format("  {:>4}  {:>11}  {:>11}  {:>11}  {:>14}  {:>9}  {:>7}  {:>10}", "k", "||f||_inf", "||f||_2",
                  "||dx||_inf", "linear solve", "inner its", "lambda", "time (s)") +
      (chord ? fmt::format("  {:>10}", "J") : "") + '\n';
  const std::string text =
      (sequential ? fmt::format("  {:>5}", block + 1) : std::string()) +
      fmt::format("  {:>4}  {:>11.4e}  {:>11.4e}  {:>11.4e}  {:>14}  {:>9}  {:>7.4g}  {:>10.3e}", record.iteration,
                  record.residual_norm, record.residual_2norm, record.step_norm,
                  has_linear_solve ? std::string(to_string(record.linear_status)) : "-",
                  has_linear_solve ? std::to_string(record.linear_iterations) : "-", record.damping, time_s) +
      (chord ? fmt::format("  {:>10}", record.jacobian_refactored == 1 ? "refactored" : "reused") : "");
  return print_record(header, text);
}

}  // namespace numlab::cli
