#include "lessons/lab.hpp"

#include <fmt/format.h>

#include <sstream>

#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "methods/linear_methods.hpp"
#include "lessons/lab_basins.hpp"
#include "numlab/linalg/measures.hpp"
#include "bench/timing.hpp"

namespace numlab::cli {

LabSession::LabSession(std::ostream& out, bool step, std::string folder, std::string title, std::string summary)
    : out_(out),
      tee_buffer_(out.rdbuf()),
      tee_(&tee_buffer_),
      pause_(step),
      folder_(std::move(folder)),
      report_(std::move(title), std::move(summary)) {}

int LabSession::TeeBuffer::overflow(int c) {
  if (c == traits_type::eof()) return traits_type::not_eof(c);
  copy_ += static_cast<char>(c);
  return terminal_->sputc(static_cast<char>(c));
}

std::streamsize LabSession::TeeBuffer::xsputn(const char* text, std::streamsize count) {
  copy_.append(text, static_cast<std::size_t>(count));
  return terminal_->sputn(text, count);
}

void LabSession::flush_free_text() {
  tee_.flush();
  report_.add_preformatted(tee_buffer_.take());
}

bool LabSession::begin_step(const std::string& title, const std::string& explanation) {
  flush_free_text();
  if (step_number_ > 0 && pause_.after_step() == StepControl::stop) return false;
  ++step_number_;
  out_ << fmt::format("\nStep {}: {}\n", step_number_, title) << std::string(title.size() + 8, '=') << '\n';
  report_.add_step(step_number_, title);
  say(explanation);
  return true;
}

void LabSession::say(const std::string& paragraph) {
  flush_free_text();
  report_.add_paragraph(paragraph);
  std::istringstream words(paragraph);
  std::string word;
  std::string line = "  ";
  while (words >> word) {
    if (line.size() + word.size() + 1 > 96 && line.size() > 2) {
      out_ << line << '\n';
      line = "  ";
    }
    if (line.size() > 2) line += ' ';
    line += word;
  }
  if (line.size() > 2) out_ << line << '\n';
  out_ << '\n';
}

void LabSession::show(const Table& table, const std::string& name) {
  flush_free_text();
  table.print(out_);
  ensure_directory(folder_);
  const std::string path = fmt::format("{}/step{}-{}.csv", folder_, step_number_, name);
  write_file_atomically(path, table.csv());
  out_ << "  (table saved as " << path << ")\n\n";
  report_.add_table(table, path);
}

void LabSession::stepper(const std::string& kind, const std::string& caption, const TraceOutput& tracer,
                         nlohmann::ordered_json extra) {
  flush_free_text();
  extra["header"] = tracer.header();
  extra["lines"] = tracer.lines();
  extra["trace"] = tracer.records();
  report_.add_stepper(kind, caption, extra);
}

void LabSession::figure(const std::string& path, const std::string& caption) {
  flush_free_text();
  out_ << "  Figure: " << path << "\n\n";
  report_.add_figure(path, caption);
}

std::string LabSession::finish() {
  flush_free_text();
  ensure_directory(folder_);
  const std::string path = folder_ + "/report.html";
  write_file_atomically(path, report_.html());
  return path;
}

const std::vector<Lab>& all_labs() {
  static const std::vector<Lab> labs = {
      {"gauss", "Gaussian elimination: pivoting, Wilkinson's growth, and GEPP against GSL LU/QR and Eigen",
       run_gauss_lab},
      {"seidel", "Gauss-Seidel: the plain system diverges, the normal equations converge at a kappa^2 price",
       run_seidel_lab},
      {"inverse2x2", "The 2x2 closed-form inverse: the determinant judged by scale, and a nearly singular 2x2",
       run_inverse2x2_lab},
      {"newton", "Newton-Raphson against GSL's eight multiroot types: quadratic convergence, Jacobian checks, failures",
       run_newton_lab},
      {"jansen", "The Jansen leg: Newton with trace, the Jacobian check, every solver over a cycle, the scene",
       run_jansen_lab},
      {"jansen-sequential", "Sequential vs full Newton: seed 000's Figure 4 done right, timing, over-modelling",
       run_jansen_sequential_lab},
      {"beest", "Seed 000's four-legged beest, drawn and animated from one solved cycle", run_beest_lab},
      {"mustang", "The Mustang roof linkage: the seed's method and why it fails, the assembly range, the scenes",
       run_mustang_lab},
      {"fit", "Least squares: the normal equations against NIST's certified digits, scaling, the foot path's arcs",
       run_fit_lab},
      {"exercises", "numlab exercise for instructors: a starter, a correct and a buggy GEPP checked, the verdicts read",
       run_exercises_lab},
      {"basins", "Basin maps: the z^3 - 1 fractal, a four-bar's two modes, the Jansen leg's branches, plain vs damped",
       run_basins_lab},
      {"robustness", "MINPACK's test set from three starts: success table, performance and data profiles, damping, dogleg",
       run_robustness_lab},
      {"linkage", "A linkage from a file: the derived model, every solver, velocities, a limit, seeds' models beside it",
       run_linkage_lab},
  };
  return labs;
}

Table linear_comparison_table(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& exact,
                              const std::vector<std::string>& methods) {
  Table table({"method", "status", "x_1", "x_n", "relative residual", "forward error", "time (median)"});
  LinearSettings settings;
  settings.max_iterations = 100000;
  for (const std::string& method : methods) {
    const DynamicResult result = run_linear_method(method, A, b, settings);
    const bool has_answer = result.x.allFinite();
    const double seconds = median_time([&] { run_linear_method(method, A, b, settings); }, {3, 200, 0.02});
    table.add_row({method, std::string(to_string(result.status)), fmt::format("{:.12g}", result.x(0)),
                   fmt::format("{:.12g}", result.x(result.x.size() - 1)),
                   has_answer ? scientific(linalg::relative_residual(A, b, result.x)) : "-",
                   has_answer ? scientific(linalg::forward_error(result.x, exact)) : "-",
                   fmt::format("{:.3g} s", seconds)});
  }
  return table;
}

}  // namespace numlab::cli
