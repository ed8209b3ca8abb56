// Lab `newton`: hand-written Newton against GSL's eight multiroot types on the MGH problems,
// its tracing, Jacobian checks (catching seed 001's slip), and the honest failures.

#include <fmt/format.h>

#include <Eigen/LU>
#include <cmath>

#include "lessons/lab.hpp"
#include "lessons/forcing_sentences.hpp"
#include "lessons/lab_sentences.hpp"
#include "methods/nonlinear_methods.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "methods/seed001_system.hpp"
#include "bench/timing.hpp"
#include "output/trace_printers.hpp"

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
  if (!session.begin_step("Newton's method, one iteration at a time",
                          "Each iteration solves J(x) dx = -f(x) (here by the hand-written GEPP) and moves to x + dx. Near "
                          "a root where J is nonsingular the residual is squared each time: the number of correct digits "
                          "doubles. Rosenbrock's system from its standard start (-1.2, 1):")) return;
  const nonlinear::TestProblem problem = nonlinear::make_test_problem("rosenbrock");
  NewtonTracer tracer(&session.out(), nullptr);
  const NonlinearRun run =
      run_nonlinear_method("newton", *problem.system, problem.standard_start, lab_settings(false), &tracer);
  session.out() << "  " << run.termination << "\n\n";
  session.stepper("newton", "Newton on Rosenbrock's system", tracer);
}

void show_jacobian_checks(LabSession& session) {
  if (!session.begin_step("Is the Jacobian right?",
                          "A wrong Jacobian entry does not stop Newton from running; it only slows it down or sends it "
                          "elsewhere. numlab compares each hand-derived Jacobian, entry by entry, with central finite "
                          "differences and with Eigen's AutoDiff (exact to rounding), and names the worst entry.")) return;
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
  if (!session.begin_step("Hand-written Newton against GSL's eight multiroot types",
                          "Every problem from its standard start, residual tolerance 1e-10, at most 100 iterations. "
                          "'distance' is ||x - x*||_inf to the known root; discrete-bvp and broyden-tridiagonal have no "
                          "closed-form root. Times are medians of repeated runs.")) return;
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
                     scientific(run.residual_norm), distance_text(problem, run.x), std::to_string(run.function_evaluations),
                     std::to_string(run.jacobian_evaluations), fmt::format("{:.3g} s", seconds)});
    }
    session.out() << "  " << problem.description << "\n";
    session.show(table, name);
  }
}

std::string point_text(const Eigen::VectorXd& x) {
  std::string text = "(";
  for (Eigen::Index i = 0; i < x.size(); ++i) text += fmt::format("{}{:.4g}", i ? ", " : "", x(i));
  return text + ")";
}

// Records every iteration, for the rate and the inner sweep counts.
struct Recorder : NewtonTraceObserver {
  std::vector<nonlinear::NewtonRecord> records;
  StepControl on_record(const nonlinear::NewtonRecord& record, int) override { records.push_back(record); return StepControl::proceed; }
};

void show_failures(LabSession& session) {
  if (!session.begin_step("Where Newton fails, or succeeds at the wrong thing",
                          "Each case below is run now; the numbers are this run's.")) return;

  // Powell singular: linear convergence.
  const nonlinear::TestProblem powell = nonlinear::make_test_problem("powell-singular");
  Recorder recorder;
  const NonlinearRun singular =
      run_nonlinear_method("newton", *powell.system, powell.standard_start, lab_settings(false), &recorder);
  const auto& r = recorder.records;
  session.say(fmt::format(
      "Powell singular: J is singular at the root, so Newton loses its quadratic rate. It needs {} iterations; "
      "over the last five, ||f|| shrinks by a factor {:.3f} per iteration (the error halves, its square "
      "quarters). It stops at ||f||_inf = {:.2g} but {:.2g} from the root: about sqrt(||f||), not ||f||.",
      singular.iterations, std::pow(r.back().residual_norm / r[r.size() - 6].residual_norm, 1.0 / 5.0),
      singular.residual_norm, singular.x.lpNorm<Eigen::Infinity>()));

  // Freudenstein-Roth: damping can make things worse.
  const nonlinear::TestProblem roth = nonlinear::make_test_problem("freudenstein-roth");
  const NonlinearRun plain = run_nonlinear_method("newton", *roth.system, roth.standard_start, lab_settings(false));
  const NonlinearRun damped = run_nonlinear_method("newton", *roth.system, roth.standard_start, lab_settings(true));
  const NonlinearRun hybrid = run_nonlinear_method("gsl-hybridsj", *roth.system, roth.standard_start, lab_settings(false));
  Eigen::MatrixXd J;
  roth.system->jacobian(damped.x, J);
  session.say(fmt::format(
      "Freudenstein-Roth from (0.5, -2): det J = 6 x2^2 - 8 x2 - 12 vanishes on the line x2 = -0.8968, where "
      "||f|| also has a local minimum that is not a root. Plain Newton jumps across the line and reaches "
      "(5, 4) after {} iterations ({}). Damped Newton only accepts steps that decrease ||f||, walks down onto "
      "the line and stalls at {} with det J = {:.2g}: {}. GSL's hybridsj stops at the local minimum {}, "
      "||f||_inf = {:.3g}: {}.",
      plain.iterations, to_string(plain.status), point_text(damped.x), J.determinant(), to_string(damped.status),
      point_text(hybrid.x), hybrid.residual_norm, to_string(hybrid.status)));

  // Arctangent: the failure damping was made for.
  const nonlinear::TestProblem arctangent = nonlinear::make_test_problem("arctangent");
  const NonlinearRun overshoot =
      run_nonlinear_method("newton", *arctangent.system, arctangent.standard_start, lab_settings(false));
  const NonlinearRun cured =
      run_nonlinear_method("newton", *arctangent.system, arctangent.standard_start, lab_settings(true));
  session.say(fmt::format(
      "Arctangent, f_i = atan(x_i) from (2, 2): each full Newton step x - atan(x)(1 + x^2) overshoots the root "
      "further, so the iterates run away to {:.2g} until J = 1/(1 + x^2) underflows to zero: {} after {} "
      "iterations. Damped Newton halves each step until ||f||^2 decreases and converges in {} ({}, ||x|| = {:.2g}). "
      "Damping cures an overshoot; it cannot cure a bad region (Freudenstein-Roth above).",
      overshoot.x.lpNorm<Eigen::Infinity>(), to_string(overshoot.status), overshoot.iterations, cured.iterations,
      to_string(cured.status), cured.x.lpNorm<Eigen::Infinity>()));

  // Wood: a root of the system that is not the minimum.
  const nonlinear::TestProblem wood = nonlinear::make_test_problem("wood");
  const NonlinearRun saddle = run_nonlinear_method("newton", *wood.system, wood.standard_start, lab_settings(false));
  int same_point = 0, methods = 0;  // methods that converge to the saddle Newton finds
  for (const MethodChoice& choice : compared_methods()) {
    const NonlinearRun run = run_nonlinear_method(choice.method, *wood.system, wood.standard_start,
                                                  lab_settings(choice.damped));
    same_point += run.status == Status::converged && (run.x - saddle.x).lpNorm<Eigen::Infinity>() < 1e-6 ? 1 : 0;
    ++methods;
  }
  session.say(fmt::format(
      "Wood: the system is (half) the gradient of Wood's function. From (-3, -1, -3, -1) Newton converges to {}, "
      "{} from (1, 1, 1, 1), and so do {} methods above: a genuine root of the system (||f||_inf = {:.2g}) but a "
      "saddle point of the function, not its minimum. Converged is not the same as right.",
      point_text(saddle.x), scientific((saddle.x - *wood.known_root).lpNorm<Eigen::Infinity>()),
      count_of(same_point, methods), saddle.residual_norm));
}

void show_linear_solvers(LabSession& session) {
  if (!session.begin_step("The inner linear solver",
                          "Newton only needs J dx = -f solved; any linalg method will do, picked with --linear. Broyden "
                          "tridiagonal (n = 10), from its standard start:")) return;
  const nonlinear::TestProblem problem = nonlinear::make_test_problem("broyden-tridiagonal");
  Table table({"--linear", "status", "iterations", "inner sweeps", "||f||_inf", "time"});
  SolverCost gepp_cost{"GEPP", 0.0, 0}, seidel_cost{"Gauss-Seidel", 0.0, 0};
  int seidel_sweeps = 0;
  for (const std::string linear : {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu"}) {
    NonlinearSettings settings = lab_settings(false);
    settings.linear = nonlinear::linear_method_named(linear);
    Recorder recorder;
    const NonlinearRun run = run_nonlinear_method("newton", *problem.system, problem.standard_start, settings, &recorder);
    int sweeps = 0;
    for (const auto& record : recorder.records) sweeps += record.linear_iterations;
    const double seconds = median_time(
        [&] { run_nonlinear_method("newton", *problem.system, problem.standard_start, settings); }, {3, 200, 0.01});
    table.add_row({linear, std::string(to_string(run.status)), std::to_string(run.iterations),
                   linear == "gauss-seidel" ? std::to_string(sweeps) : "-", scientific(run.residual_norm),
                   fmt::format("{:.3g} s", seconds)});
    if (linear == "gepp") gepp_cost = {"GEPP", seconds, run.iterations};
    if (linear == "gauss-seidel") {
      seidel_cost = {"Gauss-Seidel", seconds, run.iterations};
      seidel_sweeps = sweeps;
    }
  }
  session.show(table, "linear-solvers");
  session.say(fmt::format(
      "Gauss-Seidel on the normal equations solves each step only to ||J dx + f|| <= eta_k ||f|| (the forcing term, "
      "step 7): {} iterations and {} sweeps in all against {} iterations with GEPP's exact steps; Newton with "
      "Gauss-Seidel is {} Newton with GEPP ({:.3g} s against {:.3g} s).",
      seidel_cost.iterations, seidel_sweeps, gepp_cost.iterations,
      speed_ratio_phrase(seidel_cost.time_s, gepp_cost.time_s), seidel_cost.time_s, gepp_cost.time_s));
}

void show_sequential(LabSession& session) {
  if (!session.begin_step("Sequential Newton, with blocks found from the Jacobian's pattern",
                          "Seed 000 solves the Jansen leg's 8 closure equations as four 2x2 systems. numlab finds those "
                          "blocks itself: it pairs each equation with an unknown (a matching), then groups unknowns that "
                          "depend on each other (strongly connected components); that order is block lower-triangular.")) return;
  using mechanisms::JansenClosure;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const nonlinear::AsDynamicSystem dynamic(closure);
  const Eigen::VectorXd start = JansenClosure::seed_estimates();
  const nonlinear::SparsityPattern pattern = nonlinear::jacobian_pattern(dynamic, start);
  session.out() << "  Jacobian pattern (rows: equations 1-8, columns: theta1 ... theta8):\n";
  for (int i = 0; i < 8; ++i) {
    std::string row = "    ";
    for (int j = 0; j < 8; ++j) row += pattern(i, j) ? " x" : " .";
    session.out() << row << '\n';
  }
  const auto blocks = nonlinear::block_triangular_order(pattern);
  std::string order;
  for (const auto& block : blocks) {
    order += " {";
    for (std::size_t k = 0; k < block.unknowns.size(); ++k) {
      order += fmt::format("{}theta{}", k ? ", " : "", block.unknowns[k] + 1);
    }
    order += fmt::format(" from eqs {}-{}}}", block.equations.front() + 1, block.equations.back() + 1);
  }
  session.say("Blocks in solving order:" + order + ".");

  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  const auto full = nonlinear::newton_solve(closure, JansenClosure::seed_estimates(), options);
  nonlinear::SequentialNewton solver(dynamic, blocks, {options, nonlinear::LinearMethod::inverse2x2});
  NewtonTracer tracer(&session.out(), nullptr);
  solver.set_observer(&tracer);
  const auto sequential = solver.solve(start);
  session.stepper("newton", "Sequential Newton on seed 000's four blocks", tracer);
  std::string per_block;
  for (std::size_t b = 0; b < sequential.blocks.size(); ++b) {
    per_block += fmt::format("{}{}", b == 0 ? "" : (b + 1 == sequential.blocks.size() ? " and " : ", "),
                             sequential.blocks[b].iterations);
  }
  session.say(fmt::format(
      "At theta_i = 1.57 from seed 000's estimates, tolerance 1e-12: full Newton takes {} iterations; sequential "
      "Newton takes {} iterations in its four blocks (each a 2x2 closed-form solve). The two answers differ by "
      "{:.2g}: the roots coincide, because no block's equations contain a later block's unknowns. Any difference "
      "seed 000's Figure 4 shows comes from where each method stops, not from a different root.",
      full.iterations, per_block, (sequential.x - Eigen::VectorXd(full.x)).lpNorm<Eigen::Infinity>()));
}

// The forcing choices of the trade-off, by their --forcing names (none: the old fixed inner tolerance).
const std::vector<std::string>& forcing_choices_shown() {
  static const std::vector<std::string> names = {"none",          "constant:0.5",    "constant:0.1",
                                                 "constant:0.01", "constant:0.0001", "eisenstat-walker"};
  return names;
}

// Helical valley with Gauss-Seidel under one forcing choice: the row's numbers, and its median time.
ForcingRun helical_valley_run(const std::string& forcing, double& seconds) {
  const nonlinear::TestProblem problem = nonlinear::make_test_problem("helical-valley");
  NonlinearSettings settings = lab_settings(false);
  settings.linear = nonlinear::LinearMethod::gauss_seidel;
  settings.options.forcing = forcing_named(forcing);
  Recorder recorder;
  const NonlinearRun run = run_nonlinear_method("newton", *problem.system, problem.standard_start, settings, &recorder);
  int sweeps = 0;
  for (const auto& record : recorder.records) sweeps += record.linear_iterations;
  seconds = median_time([&] { run_nonlinear_method("newton", *problem.system, problem.standard_start, settings); },
                        {3, 200, 0.01});
  return {forcing, std::string(to_string(run.status)), run.iterations, sweeps, run.residual_norm};
}

// The Jansen leg's pose at seed 000's crank angle, fixed-size Newton with Gauss-Seidel<8> inside (as
// the crank sweep's `full --linear gauss-seidel`), under one forcing choice.
ForcingRun jansen_pose_run(const std::string& forcing, double& seconds) {
  using mechanisms::JansenClosure;
  using PoseNewton = nonlinear::Newton<JansenClosure, linalg::GaussSeidel<8>>;
  struct SweepCounter final : PoseNewton::Observer {
    int sweeps = 0;
    StepControl on_step(const PoseNewton&, const nonlinear::NewtonRecord& record) override { sweeps += record.linear_iterations; return StepControl::proceed; }
  };
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  nonlinear::NewtonOptions options = lab_settings(false).options;
  options.forcing = forcing_named(forcing);
  PoseNewton newton(closure, options, linalg::GaussSeidel<8>(nonlinear::inner_gauss_seidel_options(options.forcing)));
  SweepCounter counter;
  newton.set_observer(&counter);
  const auto result = newton.solve(JansenClosure::seed_estimates());
  newton.set_observer(nullptr);
  seconds = median_time([&] { newton.solve(JansenClosure::seed_estimates()); }, {3, 200, 0.01});
  return {forcing, std::string(to_string(result.status)), result.iterations, counter.sweeps, result.residual_norm};
}

void show_forcing_terms(LabSession& session) {
  if (!session.begin_step(
           "Inexact Newton: how accurately to solve J dx = -f",
           "An iterative inner solver need only reach ||J dx + f|| <= eta_k ||f||, eta_k the forcing term "
           "(Dembo, Eisenstat & Steihaug). A large eta_k saves inner sweeps and costs outer iterations; a small one "
           "the other way round. Eisenstat & Walker's Choice 2 sets eta_k = 0.9 (||f_k|| / ||f_k-1||)^2 with "
           "safeguards: loose while ||f|| falls slowly, tight once Newton converges fast. 'none' is the inner "
           "solver's own stop test (Gauss-Seidel: an update below 1e-9), as before forcing terms. Newton with "
           "Gauss-Seidel on the normal equations, residual tolerance 1e-10, at most 100 iterations; times are "
           "medians of repeated runs.")) return;
  const double tolerance = lab_settings(false).options.residual_tolerance;
  for (const bool jansen : {false, true}) {
    Table table({"--forcing", "status", "outer iterations", "inner sweeps", "||f||_inf", "time"});
    std::vector<ForcingRun> runs;
    for (const std::string& forcing : forcing_choices_shown()) {
      double seconds = 0.0;
      runs.push_back(jansen ? jansen_pose_run(forcing, seconds) : helical_valley_run(forcing, seconds));
      const ForcingRun& run = runs.back();
      table.add_row({run.forcing, run.status, std::to_string(run.iterations), std::to_string(run.sweeps),
                     scientific(run.residual), fmt::format("{:.3g} s", seconds)});
    }
    session.out() << (jansen ? "  The Jansen leg's pose at theta_i = 1.57 from seed 000's estimates (8 unknowns):\n"
                             : "  Helical valley from its standard start (n = 3):\n");
    session.show(table, jansen ? "forcing-jansen" : "forcing-helical-valley");
    session.say(forcing_tradeoff_sentence(runs, tolerance));
  }
}

}  // namespace

int run_newton_lab(LabSession& session) {
  show_quadratic_convergence(session);
  show_jacobian_checks(session);
  show_comparison(session);
  show_failures(session);
  show_linear_solvers(session);
  show_sequential(session);
  show_forcing_terms(session);
  return 0;
}

}  // namespace numlab::cli
