#include "bench/robustness_runs.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bench/timing.hpp"
#include "methods/nonlinear_methods.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

namespace numlab::cli {

namespace {

// The system seen by a solver, counting every f and every J it asks for.
class CountingSystem final : public nonlinear::DynamicSystem {
 public:
  explicit CountingSystem(const nonlinear::DynamicSystem& system) : system_(system) {}
  int dimension() const override { return system_.dimension(); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override {
    ++functions;
    system_.residual(x, f);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    ++jacobians;
    system_.jacobian(x, J);
  }
  void residual_and_jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& f, Eigen::MatrixXd& J) const override {
    ++functions;
    ++jacobians;
    system_.residual_and_jacobian(x, f, J);
  }
  mutable int functions = 0;
  mutable int jacobians = 0;

 private:
  const nonlinear::DynamicSystem& system_;
};

nonlinear::NewtonOptions budget(bool damped, int n) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = solved_tolerance;
  options.max_iterations = robustness_iteration_limit(n);
  options.damped = damped;
  return options;
}

// One solve: the final x and the solver's status.
struct Outcome {
  Eigen::VectorXd x;
  Status status;
  int iterations;
  std::string termination;
};

Outcome solve_once(const std::string& solver, const nonlinear::DynamicSystem& system, const Eigen::VectorXd& x0,
                   const std::vector<nonlinear::Block>& blocks) {
  if (solver.starts_with("gsl-")) {
    const NonlinearRun run =
        run_nonlinear_method(solver, system, x0, {budget(false, system.dimension()), nonlinear::LinearMethod::gepp});
    return {run.x, run.status, run.iterations, run.termination};
  }
  if (solver == "dogleg") {
    const nonlinear::NewtonOptions options = budget(false, system.dimension());
    const auto result = nonlinear::dogleg_solve(system, x0, options);
    return {result.x, result.status, result.iterations, nonlinear::termination_line(result, options)};
  }
  if (solver.starts_with("sequential")) {
    nonlinear::SequentialNewtonOptions options;
    options.newton = budget(solver == "sequential-damped", system.dimension());
    const auto result = nonlinear::sequential_newton(system, blocks, x0, options);
    const std::string where = result.failed_block < 0 ? "" : fmt::format(" in block {}", result.failed_block + 1);
    return {result.x, result.status, result.iterations,
            fmt::format("Termination: {}{} (||f||_inf = {:.3g} after {} iterations)", to_string(result.status), where,
                        result.residual_norm, result.iterations)};
  }
  const bool damped = solver.starts_with("damped-");
  const std::string linear = solver.substr(solver.find('-') + 1);
  const NonlinearRun run =
      run_nonlinear_method("newton", system, x0, {budget(damped, system.dimension()), nonlinear::linear_method_named(linear)});
  return {run.x, run.status, run.iterations, run.termination};
}

RobustnessRun run_case(int case_index, const nonlinear::MinpackInstance& instance, const std::string& solver,
                       const std::vector<nonlinear::Block>& blocks, int repeats) {
  const nonlinear::DynamicSystem& system = *instance.problem.system;
  const int n = system.dimension();
  RobustnessRun run;
  run.case_index = case_index;
  run.solver = solver;
  if (solver.ends_with("inverse2x2") && n != 2) {
    run.applies = false;
    run.not_applicable = "inverse2x2 needs n = 2";
    return run;
  }
  if (solver.starts_with("sequential") && blocks.size() < 2) {
    run.applies = false;
    run.not_applicable = "one block: the Jacobian's sparsity does not split the system";
    return run;
  }
  CountingSystem counted(system);
  const auto began = std::chrono::steady_clock::now();
  const Outcome outcome = solve_once(solver, counted, instance.start, blocks);
  const double once_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  Eigen::VectorXd f(n);
  if (outcome.x.allFinite()) system.residual(outcome.x, f);
  run.status = outcome.status;
  run.iterations = outcome.iterations;
  run.termination = outcome.termination;
  run.residual_norm = outcome.x.allFinite() && f.allFinite() ? f.lpNorm<Eigen::Infinity>()
                                                             : std::numeric_limits<double>::quiet_NaN();
  run.solved = run.residual_norm <= solved_tolerance;  // false for NaN
  run.function_evaluations = counted.functions;
  run.jacobian_evaluations = counted.jacobians;
  run.evaluations = counted.functions + static_cast<double>(n) * counted.jacobians;
  // Only a solved run's time enters a profile: a failed one is timed once (a failure that spends
  // the whole budget would otherwise cost most of the benchmark's time, for no figure).
  const TimingPlan plan{repeats, repeats, 0.0};
  run.time_s = run.solved && repeats > 1 ? median_time([&] { solve_once(solver, system, instance.start, blocks); }, plan)
                                         : once_s;
  return run;
}

}  // namespace

const RobustnessRun& RobustnessResults::run(int case_index, const std::string& solver) const {
  for (const RobustnessRun& candidate : runs) {
    if (candidate.case_index == case_index && candidate.solver == solver) return candidate;
  }
  throw std::out_of_range("no run of " + solver + " on case " + std::to_string(case_index));
}

std::vector<std::string> robustness_solvers() {
  std::vector<std::string> solvers;
  for (const char* kind : {"newton-", "damped-"}) {
    for (const std::string& linear : nonlinear::newton_linear_methods()) solvers.push_back(kind + linear);
  }
  // Built in place (a moved temporary string here trips GCC 12's -Warray-bounds false positive).
  solvers.emplace_back("dogleg");
  solvers.emplace_back("sequential");
  solvers.emplace_back("sequential-damped");
  for (const std::string& type : nonlinear::gsl_multiroot_types()) solvers.push_back("gsl-" + type);
  return solvers;
}

bool applies_everywhere(const std::string& solver) {
  return !solver.ends_with("inverse2x2") && !solver.starts_with("sequential");
}

RobustnessResults run_robustness(const std::vector<nonlinear::MinpackCase>& cases, int repeats,
                                 void (*progress)(const std::string&)) {
  RobustnessResults results{cases, robustness_solvers(), {}, repeats};
  for (std::size_t c = 0; c < cases.size(); ++c) {
    if (progress != nullptr) progress("bench robustness: " + nonlinear::case_label(cases[c]));
    const nonlinear::MinpackInstance instance = nonlinear::make_minpack_instance(cases[c]);
    std::vector<nonlinear::Block> blocks;
    try {
      blocks = nonlinear::block_triangular_order(nonlinear::jacobian_pattern(*instance.problem.system, instance.start));
    } catch (const std::invalid_argument&) {
      blocks.clear();  // structurally singular at the start: no block order, sequential does not apply
    }
    for (const std::string& solver : results.solvers) {
      results.runs.push_back(run_case(static_cast<int>(c), instance, solver, blocks, repeats));
    }
  }
  return results;
}

std::string outcome_text(const RobustnessRun& run) {
  if (!run.applies) return "n/a";
  if (run.solved) return "solved";
  return fmt::format("{} {:.1e}", to_string(run.status), run.residual_norm);
}

}  // namespace numlab::cli
