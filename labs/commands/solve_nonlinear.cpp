#include "commands/solve_nonlinear.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>

#include "parsing/argument_parsing.hpp"
#include "methods/nonlinear_methods.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/minpack_cases.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

namespace {

// settings.options.forcing from --forcing: the default (Eisenstat-Walker) when not given. Given, it
// must apply (require_applies: --method newton with an iterative --linear, gauss-seidel).
nonlinear::ForcingOptions forcing_option(const std::optional<std::string>& text, bool is_newton,
                                         nonlinear::LinearMethod linear) {
  const bool iterative = linear == nonlinear::LinearMethod::gauss_seidel;
  require_applies(text.has_value(), is_newton && iterative, "--forcing",
                  "--method newton with an iterative --linear (gauss-seidel); direct solvers solve exactly");
  return text ? forcing_named(*text) : nonlinear::ForcingOptions{};
}

// settings.options.reuse_jacobian from --reuse-jacobian K: 1 (Newton) when not given. Given, K must
// be at least 1 and apply (--method newton with --linear gepp, the solver that keeps its factors).
int reuse_jacobian_option(std::optional<int> every, bool is_newton, nonlinear::LinearMethod linear) {
  if (every && *every < 1) {
    throw std::invalid_argument(fmt::format("--reuse-jacobian {}: K must be at least 1 (1 is plain Newton)", *every));
  }
  require_applies(every.has_value(), is_newton && linear == nonlinear::LinearMethod::gepp, "--reuse-jacobian",
                  "--method newton with --linear gepp (the chord method reuses GEPP's kept factors)");
  return every.value_or(1);
}

}  // namespace

Eigen::VectorXd parse_point(const std::string& text, int expected, const std::string& flag) {
  const std::vector<double> values = parse_number_list(text, flag);
  if (static_cast<int>(values.size()) != expected) {
    throw std::invalid_argument(
        fmt::format("{} {} has {} numbers but the problem has {} unknowns", flag, linalg::quoted_token(text), values.size(),
                    expected));
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), expected);
}

ChosenProblem choose_problem(const std::string& name, std::optional<int> size, std::optional<int> start_factor,
                             const std::optional<std::string>& x0) {
  const nonlinear::ProblemSizes sizes = nonlinear::problem_sizes(name);
  const int largest = std::min(sizes.largest, largest_cli_problem_size);
  if (size && (*size < sizes.smallest || *size > largest)) {
    const std::string allowed = sizes.fixed() ? nonlinear::describe_sizes(sizes)
                                              : fmt::format("n = {}..{}", sizes.smallest, largest);
    throw std::invalid_argument(fmt::format("--size {}: {} has {}", *size, name, allowed));
  }
  if (start_factor && x0) throw std::invalid_argument("--start and --x0 both give the start: use one");
  nonlinear::TestProblem problem = nonlinear::make_test_problem(name, size.value_or(sizes.default_size));
  const int n = problem.system->dimension();
  if (x0) {
    if (x0->empty()) throw std::invalid_argument("--x0 needs numbers a,b,... (or leave it out for the standard start)");
    Eigen::VectorXd point = parse_point(*x0, n, "--x0");
    return {std::move(problem), std::move(point), "given"};
  }
  const int factor = start_factor.value_or(1);
  Eigen::VectorXd point = nonlinear::minpack_start(name, problem.standard_start, factor);
  return {std::move(problem), std::move(point), fmt::format("{}x0", factor)};
}

SolveNonlinearCommand::SolveNonlinearCommand(CLI::App& solve) {
  command_ = solve.add_subcommand("nonlinear", "Solve one nonlinear test system f(x) = 0");
  command_->add_option("--problem", problem_, "Moré-Garbow-Hillstrom problem")
      ->required()
      ->check(CLI::IsMember(nonlinear::test_problem_names()));
  command_->add_option("--method", method_, "newton or dogleg (hand-written), or gsl-<type>")
      ->required()
      ->check(CLI::IsMember(nonlinear_method_names()));
  command_->add_option("--x0", x0_, "Starting point a,b,... (default: the problem's standard start)");
  command_->add_option("--start", start_factor_, "MINPACK's start: 1, 10 or 100 times x0 (default 1; not with --x0)")
      ->check(CLI::IsMember({1, 10, 100}));
  command_->add_option("--size", size_, "Size n of a variable-size problem (default: docs/cli.md)");
  command_->add_option("--linear", linear_, "Newton's inner linear solver (newton only)")
      ->check(CLI::IsMember(nonlinear::newton_linear_methods()));
  command_->add_flag("--damped", damped_, "Backtracking on ||f||^2 (newton only; off by default)");
  command_->add_option("--step-tol", step_tolerance_, "Relative step tolerance (default 1e-12)")
      ->check(finite_non_negative());
  command_->add_option("--forcing", forcing_, std::string("Inexact Newton's forcing term eta_k: ") + forcing_choices +
                                                   " (default eisenstat-walker; newton with gauss-seidel only)");
  command_->add_option("--reuse-jacobian", reuse_jacobian_,
                       "Chord method: factor J every K iterations, reuse its factors between (newton with gepp; 1: Newton)");
  add_common_options(*command_, common_);
}

namespace {

// What solve nonlinear prints: the command's choices and the run's outcome.
struct NonlinearOutcome {
  const std::string& problem_name;
  const std::string& method;
  const std::string& linear;
  bool damped;
  std::optional<int> reuse_jacobian;
  const ChosenProblem& chosen;
  const NonlinearRun& run;
  double time_s;
  double distance;  // to the known root; NaN when none is known
  bool newton() const { return method == "newton"; }
};

void print_nonlinear_json(const NonlinearOutcome& o, const nlohmann::ordered_json* trace) {
  const NonlinearRun& run = o.run;
  nlohmann::ordered_json out = {{"problem", o.problem_name},
                                {"method", o.method},
                                {"size", o.chosen.problem.system->dimension()},
                                {"start", o.chosen.start},
                                {"x", nlohmann::ordered_json::array()},
                                {"status", std::string(to_string(run.status))},
                                {"iterations", run.iterations},
                                {"residual_inf", number_or_null(run.residual_norm)},
                                {"function_evaluations", run.function_evaluations},
                                {"jacobian_evaluations", run.jacobian_evaluations},
                                {"time_s", o.time_s}};
  for (double value : run.x) out["x"].push_back(number_or_null(value));
  if (o.newton()) {
    out["linear"] = o.linear;
    out["damped"] = o.damped;
  }
  if (o.reuse_jacobian) {
    out["reuse_jacobian"] = *o.reuse_jacobian;
    out["factorizations"] = run.factorizations;
  }
  out["step_inf"] = number_or_null(run.step_norm);
  if (o.chosen.problem.known_root) out["distance_to_root"] = number_or_null(o.distance);
  out["termination"] = run.termination;
  if (trace != nullptr) out["trace"] = *trace;
  std::cout << out.dump(2) << '\n';
}

void print_nonlinear_csv(const NonlinearOutcome& o) {
  const NonlinearRun& run = o.run;
  const int n = o.chosen.problem.system->dimension();
  std::cout << "problem,method,status,iterations,residual_inf,function_evaluations,jacobian_evaluations,time_s,size,"
               "start";
  for (int i = 0; i < n; ++i) std::cout << ",x" << i + 1;
  std::cout << '\n'
            << fmt::format("{},{},{},{},{:.6g},{},{},{:.6g}", o.problem_name, o.method, to_string(run.status),
                           run.iterations, run.residual_norm, run.function_evaluations, run.jacobian_evaluations,
                           o.time_s)
            << fmt::format(",{},{}", n, o.chosen.start);
  for (double value : run.x) std::cout << fmt::format(",{:.17g}", value);
  std::cout << '\n';
}

void print_nonlinear_text(const NonlinearOutcome& o) {
  const NonlinearRun& run = o.run;
  std::string x_text;
  for (double value : run.x) x_text += fmt::format("{:.12g} ", value);
  std::cout << fmt::format("problem            {} - {}\n", o.problem_name, o.chosen.problem.description)
            << fmt::format("size, start        n = {}, {}\n", o.chosen.problem.system->dimension(), o.chosen.start)
            << fmt::format("method             {}{}\n", o.method,
                           o.newton() ? fmt::format(" (linear solver {}{})", o.linear, o.damped ? ", damped" : "") : "")
            << fmt::format("status             {}\n", to_string(run.status))
            << fmt::format("x                  {}\n", x_text)
            << fmt::format("iterations         {}\n", run.iterations)
            << fmt::format("||f||_inf          {:.3g}\n", run.residual_norm);
  if (o.chosen.problem.known_root) std::cout << fmt::format("distance to root   {:.3g}   (||x - x*||_inf)\n", o.distance);
  std::cout << fmt::format("evaluations        {} of f, {} of J\n", run.function_evaluations, run.jacobian_evaluations);
  if (o.reuse_jacobian) {
    std::cout << fmt::format("factorizations     {} (J refactored every {} iterations)\n", run.factorizations,
                             *o.reuse_jacobian);
  }
  std::cout << fmt::format("time               {:.3g} s\n", o.time_s) << run.termination << '\n';
}

}  // namespace

int SolveNonlinearCommand::run() const {
  // 1. Every flag checked against the method before any work (docs/cli.md, "Which flags apply where").
  const CommonOptions common = checked_common_options(common_, "solve nonlinear");
  const bool is_newton = method_ == "newton";
  require_applies(damped_, is_newton, "--damped", "--method newton (GSL's types take no damping)");
  require_applies(given(*command_, "--linear"), is_newton, "--linear", "--method newton");
  const ChosenProblem chosen = choose_problem(problem_, size_, start_factor_,
                                              given(*command_, "--x0") ? std::optional(x0_) : std::nullopt);
  const nonlinear::TestProblem& problem = chosen.problem;
  const Eigen::VectorXd& x0 = chosen.x0;

  NonlinearSettings settings;
  settings.linear = nonlinear::linear_method_named(linear_);
  settings.options.damped = damped_;
  if (common.tolerance) settings.options.residual_tolerance = *common.tolerance;
  if (common.max_iterations) settings.options.max_iterations = *common.max_iterations;
  if (step_tolerance_) settings.options.step_tolerance = *step_tolerance_;
  settings.options.forcing = forcing_option(forcing_, is_newton, settings.linear);
  settings.options.reuse_jacobian = reuse_jacobian_option(reuse_jacobian_, is_newton, settings.linear);

  // 2. Solve, traced: text and CSV traces go to stderr (JSON's too with --step, so that each pause
  // follows a shown step); the time leaves out the pauses.
  StepPause pause(common.step);
  NewtonTracer tracer(common.trace && (common.step || common.format != Format::json) ? &std::cerr : nullptr, &pause);
  const auto begin = std::chrono::steady_clock::now();
  const NonlinearRun run = run_nonlinear_method(method_, *problem.system, x0, settings, common.trace ? &tracer : nullptr);
  if (pause.stopped()) return report_stopped(common, {{"problem", problem_}, {"method", method_}}, tracer.records());
  const double time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() - pause.seconds_waited();
  const double distance = problem.known_root ? (run.x - *problem.known_root).lpNorm<Eigen::Infinity>()
                                             : std::numeric_limits<double>::quiet_NaN();

  const NonlinearOutcome outcome{problem_, method_, linear_, damped_, reuse_jacobian_, chosen, run, time_s, distance};
  if (common.format == Format::json) {
    print_nonlinear_json(outcome, common.trace ? &tracer.records() : nullptr);
  } else if (common.format == Format::csv) {
    print_nonlinear_csv(outcome);
  } else {
    print_nonlinear_text(outcome);
  }
  return exit_code_for(run.status);
}

}  // namespace numlab::cli
