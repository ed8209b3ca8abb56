// Lab `newton`: hand-written Newton against GSL's eight multiroot types on the MGH problems,
// its tracing, Jacobian checks (catching seed 001's slip), and the honest failures.

#include <fmt/format.h>

#include <cmath>

#include "lab.hpp"
#include "nonlinear_methods.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/test_problems.hpp"
#include "seed001_system.hpp"
#include "timing.hpp"
#include "trace_printers.hpp"

namespace numlab::cli {

namespace {

// The methods of the comparison: Newton plain and damped, then GSL's eight types.
struct MethodChoice {
  std::string label;
  std::string method;
  bool damped;
};

std::vector<MethodChoice> compared_methods() {
  std::vector<MethodChoice> methods = {{"newton", "newton", false}, {"newton --damped", "newton", true}};
  for (const std::string& name : nonlinear_method_names()) {
    if (name != "newton") methods.push_back({name, name, false});
  }
  return methods;
}

NonlinearSettings lab_settings(bool damped) {
  NonlinearSettings settings;
  settings.options.residual_tolerance = 1e-10;
  settings.options.max_iterations = 100;
  settings.options.damped = damped;
  return settings;
}

std::string distance_text(const nonlinear::TestProblem& problem, const Eigen::VectorXd& x) {
  if (!problem.known_root) return "-";
  return scientific((x - *problem.known_root).lpNorm<Eigen::Infinity>());
}

void show_quadratic_convergence(LabSession& session) {
  session.begin_step("Newton's method, one iteration at a time",
                     "Each iteration solves J(x) dx = -f(x) (here by the hand-written GEPP) and moves to x + dx. Near "
                     "a root where J is nonsingular the residual is squared each time: the number of correct digits "
                     "doubles. Rosenbrock's system from its standard start (-1.2, 1):");
  const nonlinear::TestProblem problem = nonlinear::make_test_problem("rosenbrock");
  NewtonTracer tracer(&session.out(), false);
  const NonlinearRun run =
      run_nonlinear_method("newton", *problem.system, problem.standard_start, lab_settings(false), &tracer);
  session.out() << "  " << run.termination << "\n\n";
}

void show_jacobian_checks(LabSession& session) {
  session.begin_step("Is the Jacobian right?",
                     "A wrong Jacobian entry does not stop Newton from running; it only slows it down or sends it "
                     "elsewhere. numlab compares each hand-derived Jacobian, entry by entry, with central finite "
                     "differences and with Eigen's AutoDiff (exact to rounding), and names the worst entry.");
  Table problems({"problem", "worst entry", "relative error", "finite differences vs AutoDiff", "verdict"});
  for (const std::string& name : nonlinear::test_problem_names()) {
    const nonlinear::TestProblem problem = nonlinear::make_test_problem(name);
    const nonlinear::JacobianCheck check = nonlinear::check_jacobian(*problem.system, problem.standard_start);
    problems.add_row({name, fmt::format("J({},{})", check.worst_row + 1, check.worst_column + 1),
                      scientific(check.worst_error), scientific(check.finite_difference_agreement),
                      check.agrees ? "agrees" : "WRONG"});
  }
  session.show(problems, "jacobian-checks");

  const Eigen::VectorXd estimates = Seed001Closure::seed_estimates();
  const nonlinear::JacobianCheck correct =
      nonlinear::check_jacobian(Seed001Closure(Seed001Closure::seed_crank_angle, false), estimates);
  const nonlinear::JacobianCheck slipped =
      nonlinear::check_jacobian(Seed001Closure(Seed001Closure::seed_crank_angle, true), estimates);
  session.say(fmt::format("Seed 001's ten closure equations at its own estimates (theta2 = {}): with |r12| = 65.7 "
                          "in the Jacobian the check agrees (worst relative error {:.2g}). With the seed's printed "
                          "67.5 in rows 9 and 10 it does not: {}.",
                          Seed001Closure::seed_crank_angle, correct.worst_error, describe_worst_entry(slipped)));
}

void show_comparison(LabSession& session) {
  session.begin_step("Hand-written Newton against GSL's eight multiroot types",
                     "Every problem from its standard start, residual tolerance 1e-10, at most 100 iterations. "
                     "'distance' is ||x - x*||_inf to the known root; discrete-bvp and broyden-tridiagonal have no "
                     "closed-form root. Times are medians of repeated runs.");
  for (const std::string& name : nonlinear::test_problem_names()) {
    const nonlinear::TestProblem problem = nonlinear::make_test_problem(name);
    Table table({"method", "status", "iterations", "||f||_inf", "distance", "f evals", "J evals", "time"});
    for (const MethodChoice& choice : compared_methods()) {
      const NonlinearSettings settings = lab_settings(choice.damped);
      const NonlinearRun run = run_nonlinear_method(choice.method, *problem.system, problem.standard_start, settings);
      const double seconds = median_time(
          [&] { run_nonlinear_method(choice.method, *problem.system, problem.standard_start, settings); },
          {3, 200, 0.01});
      table.add_row({choice.label, std::string(to_string(run.status)), std::to_string(run.iterations),
                     scientific(run.residual_inf), distance_text(problem, run.x), std::to_string(run.function_evaluations),
                     std::to_string(run.jacobian_evaluations), fmt::format("{:.3g} s", seconds)});
    }
    session.out() << "  " << problem.description << "\n";
    session.show(table, name);
  }
}

}  // namespace

int run_newton_lab(LabSession& session) {
  show_quadratic_convergence(session);
  show_jacobian_checks(session);
  show_comparison(session);
  return 0;
}

}  // namespace numlab::cli
