#include "bench/bench_jansen.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>

#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_sequential.hpp"
#include "numlab/mechanisms/full_newton_pose_solver.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "output/table.hpp"
#include "bench/timing.hpp"

namespace numlab::cli {

namespace {

using mechanisms::JansenModel;

// The row "full, std::sin": full Newton (GEPP) on the textbook closure, whose sines come from
// std::sin and std::cos rather than the table every other row's closure uses.
constexpr const char* library_sines = "full-std-sin";
// The row "sequential, textbook": the four Newton<DyadBlock, ClosedForm2x2> a student reads
// (TextbookSequentialJansen), beside `sequential`, their specialised copy DyadNewton.
constexpr const char* textbook_sequential = "sequential-textbook";

std::unique_ptr<mechanisms::JansenPoseSolver> make_solver(JansenModel model, const std::string& label,
                                                          const std::string& solver, const std::string& linear,
                                                          const nonlinear::NewtonOptions& options) {
  if (label == textbook_sequential) return std::make_unique<mechanisms::TextbookSequentialJansen>(options);
  if (label != library_sines) return mechanisms::make_jansen_solver(model, solver, linear, options);
  if (model == JansenModel::eight_equations) {
    return mechanisms::make_full_newton<mechanisms::JansenClosure, Eigen::VectorXd>(linear, options);
  }
  return mechanisms::make_full_newton<mechanisms::Jansen10Closure, Eigen::VectorXd>(linear, options);
}

struct SolverChoice {
  std::string label, solver, linear;
};

std::vector<SolverChoice> solver_choices(JansenModel model, bool quick) {
  std::vector<SolverChoice> choices = {{"full", "full", "gepp"},
                                       {library_sines, "full", "gepp"},
                                       {"full-gauss-seidel", "full", "gauss-seidel"},
                                       {"full-gsl-lu", "full", "gsl-lu"},
                                       {"full-eigen-lu", "full", "eigen-lu"},
                                       {"sequential", "sequential", "gepp"}};
  if (model == JansenModel::eight_equations) choices.push_back({textbook_sequential, "sequential", "inverse2x2"});
  choices.push_back({"analytic", "analytic", "gepp"});
  for (const std::string& type : nonlinear::gsl_multiroot_types()) {
    if (!quick || type == "newton") choices.push_back({"gsl-" + type, "gsl-" + type, "gepp"});
  }
  return choices;
}

double time_of(const std::vector<JansenBenchRow>& rows, const std::string& solver) {
  for (const auto& row : rows) {
    if (row.solver == solver) return row.time_s;
  }
  return std::nan("");
}

}  // namespace

std::string jansen_bench_label(const std::string& solver) {
  if (solver == library_sines) return "full, std::sin";
  if (solver == textbook_sequential) return "sequential, textbook";
  if (solver.starts_with("file-")) return "jansen.toml, " + solver.substr(5);
  return solver;
}

std::vector<JansenBenchRow> bench_jansen(JansenModel model, double tolerance, bool quick) {
  // A cycle is 360 poses, 1 degree apart, starting at the seed's crank angle (no walk-in).
  const double start = mechanisms::JansenClosure::seed_crank_angle * 180.0 / std::numbers::pi;
  nonlinear::NewtonOptions options;
  options.residual_tolerance = tolerance;
  options.max_iterations = 100;
  const TimingPlan plan = quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3};
  std::vector<JansenBenchRow> rows;
  for (const SolverChoice& choice : solver_choices(model, quick)) {
    if (isatty(STDERR_FILENO) != 0) std::cerr << "\r\033[Kbench jansen: " << choice.label << std::flush;
    const auto solver = make_solver(model, choice.label, choice.solver, choice.linear, options);
    // Timed: the sweep solve itself, the same for every solver (the start from the seed's
    // estimates, 360 predictions and pose solves, the angles stored). Not timed: the joints and
    // the checks against the closed form, computed once afterwards from the same solver.
    const auto cycle = [&] { return mechanisms::solve_crank_sweep(model, *solver, start, start + 359.0, 1.0); };
    const mechanisms::JansenSweepAngles solved = cycle();
    int iterations = 0;
    for (const auto& outcome : solved.outcomes) iterations += outcome.iterations;
    const mechanisms::JansenSweep checked = mechanisms::crank_sweep(model, *solver, start, start + 359.0, 1.0);
    const double error = checked.status == Status::converged ? checked.worst_closed_form_distance
                                                             : std::numeric_limits<double>::infinity();
    rows.push_back({choice.label, model, tolerance, median_time(cycle, plan), error, iterations});
  }
  if (isatty(STDERR_FILENO) != 0) std::cerr << "\r\033[K" << std::flush;
  return rows;
}

void print_jansen_bench(std::ostream& out, const std::vector<JansenBenchRow>& rows) {
  const double analytic = time_of(rows, "analytic"), gsl_newton = time_of(rows, "gsl-newton");
  const double full = time_of(rows, "full"), sequential = time_of(rows, "sequential");
  out << fmt::format("Median time per 360-pose crank cycle, Newton tolerance {:g}; error = worst joint distance from "
                     "the closed form.\n\n",
                     rows.empty() ? 0.0 : rows.front().tolerance);
  Table table({"solver", "time per cycle", "per pose", "x closed form", "iterations", "error"});
  for (const auto& row : rows) {
    table.add_row({jansen_bench_label(row.solver), fmt::format("{:.3g} s", row.time_s), fmt::format("{:.3g} us", row.time_s / 360 * 1e6),
                   fmt::format("{:.2f}", row.time_s / analytic), std::to_string(row.iterations), scientific(row.error)});
  }
  table.print(out);
  auto verdict = [](bool met) { return met ? "met" : "NOT met"; };
  out << fmt::format("\nTargets:\n  full Newton (GEPP) vs GSL newton:  {:.2f}x faster   (target >= 3x: {})\n",
                     gsl_newton / full, verdict(gsl_newton / full >= 3.0))
      << fmt::format("  sequential vs full Newton:         {:.2f}x faster   (target >= 2.5x: {})\n", full / sequential,
                     verdict(full / sequential >= 2.5))
      << fmt::format("  full Newton vs the closed form:    {:.2f}x slower   (target <= 4x: {})\n", full / analytic,
                     verdict(full / analytic <= 4.0));
  const double file_full = time_of(rows, "file-full"), file_sequential = time_of(rows, "file-sequential");
  if (!std::isnan(file_full)) {
    out << fmt::format("  jansen.toml (derived) vs hand-coded, full:        {:.2f}x slower   (goal <= 2x: {})\n",
                       file_full / full, verdict(file_full / full <= 2.0))
        << fmt::format("  jansen.toml (derived) vs hand-coded, sequential:  {:.2f}x slower   (goal <= 2x: {})\n",
                       file_sequential / sequential, verdict(file_sequential / sequential <= 2.0));
  }
}

}  // namespace numlab::cli
