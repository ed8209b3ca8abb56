#include "commands/solve_linear.hpp"

#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "parsing/argument_parsing.hpp"
#include "methods/linear_methods.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

namespace {

struct LoadedSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  std::optional<Eigen::VectorXd> exact_solution;
  std::string description;
};

// "KIND:N" (N may be left out for gs-diverge).
LoadedSystem generated_system(const std::string& spec, unsigned seed) {
  const GeneratorSpec parsed =
      parse_generator_spec(spec, linalg::generator_kinds(), "gs-diverge", linalg::max_generated_size, "--generate");
  const std::string& kind = parsed.kind;
  const int n = parsed.size.value_or(3);
  linalg::GeneratedSystem generated = linalg::generate_system(kind, n, seed);
  const std::string description = fmt::format("{}, n = {} (b = A * ones, so the exact solution is all ones)", kind,
                                              generated.A.rows());
  return {generated.A, generated.b, generated.exact_solution, description};
}

// --matrix FILE [--rhs FILE]: a square A with --rhs; else [A | b] (n x n+1); else A alone with b = A * ones.
LoadedSystem file_system(const std::string& matrix_file, const std::string& rhs_file) {
  const Eigen::MatrixXd values = linalg::read_matrix_file(matrix_file);
  const auto shape = fmt::format("{}x{}", values.rows(), values.cols());
  if (!rhs_file.empty()) {
    if (values.rows() != values.cols()) {
      throw std::invalid_argument(matrix_file + ": the matrix is " + shape + ", not square");
    }
    const Eigen::VectorXd b = linalg::read_vector_file(rhs_file);
    if (b.size() != values.rows()) {
      throw std::invalid_argument(fmt::format("{}: right-hand side has {} entries but the matrix has {} rows", rhs_file,
                                              b.size(), values.rows()));
    }
    return {values, b, std::nullopt, fmt::format("{} ({}), right-hand side {}", matrix_file, shape, rhs_file)};
  }
  if (values.cols() == values.rows() + 1) {
    return {values.leftCols(values.rows()), values.col(values.cols() - 1), std::nullopt,
            fmt::format("{} (augmented [A | b], n = {})", matrix_file, values.rows())};
  }
  if (values.rows() == values.cols()) {
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(values.rows());
    return {values, values * ones, ones,
            fmt::format("{} (n = {}; b = A * ones, so the exact solution is all ones)", matrix_file, values.rows())};
  }
  throw std::invalid_argument(matrix_file + ": the matrix is " + shape +
                              "; expected a square A (with --rhs, or b = A * ones) or an augmented n x (n+1) [A | b]");
}

// Warnings that stop a meaningless answer from passing for a good one.
std::string warning_for(const DynamicResult& result, double condition_estimate) {
  constexpr double epsilon = std::numeric_limits<double>::epsilon();
  std::string warning;
  if (std::isfinite(result.growth_factor) && result.growth_factor * epsilon >= 1e-8) {
    warning += fmt::format(
        "Growth factor {:.3g}: rounding errors may be amplified by that much (growth * eps = {:.2g}), so digits "
        "are lost even though every pivot was acceptable. ",
        result.growth_factor, result.growth_factor * epsilon);
  }
  if (condition_estimate * epsilon >= 1.0) {
    warning += fmt::format(
        "Condition estimate {:.3g} exceeds 1/eps: the matrix is singular to working precision and the answer may "
        "have no correct digits.",
        condition_estimate);
  } else if (condition_estimate * epsilon >= 1e-3) {
    warning += fmt::format("Condition estimate {:.3g}: expect to lose about {:.0f} of 16 digits.", condition_estimate,
                           std::log10(condition_estimate));
  }
  while (!warning.empty() && warning.back() == ' ') warning.pop_back();
  return warning;
}

// Why Gauss-Seidel's sweeps stopped without a solution (no_progress): the numbers behind the status.
std::string unsolved_warning(const LoadedSystem& system, const DynamicResult& result) {
  const double b_norm = system.b.lpNorm<Eigen::Infinity>();
  const double scale = system.A.cwiseAbs().rowwise().sum().maxCoeff() * result.x.lpNorm<Eigen::Infinity>() + b_norm;
  return fmt::format(
      "The sweeps settled (last step {:.3g}) on an x that does not solve A x = b: ||b - A x||_inf = {:.3g} "
      "({:.3g} of ||b||_inf; backward error {:.3g}). On the normal equations the sweeps settle at a "
      "least-squares solution: the system may be inconsistent (no x solves it). ",
      result.step_norm, result.residual_norm, result.residual_norm / b_norm, result.residual_norm / scale);
}

std::string vector_text(const Eigen::VectorXd& x) {
  constexpr Eigen::Index shown = 8;
  std::string text;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (x.size() > shown && i == shown - 2) {
      text += fmt::format("... ({} more) ", x.size() - shown);
      i = x.size() - 2;
    }
    text += fmt::format("{:.10g} ", x(i));
  }
  return text;
}

// Everything the three output formats print about one solve.
struct SolveReport {
  std::string method;
  const LoadedSystem& system;
  const DynamicResult& result;
  double time_s;
  bool has_answer;          // x is finite
  bool iterative;           // Gauss-Seidel
  double relative_residual; // NaN without an answer
  double forward_error;     // NaN without an answer or a known exact solution
  double condition;
  std::string warning;
};

SolveReport measure(const std::string& method, const LoadedSystem& system, const DynamicResult& result, double time_s) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const bool has_answer = result.x.allFinite();
  const double condition = linalg::condition_estimate(system.A);
  const bool unsolved = method.starts_with("gauss-seidel") && result.status == Status::no_progress && has_answer;
  std::string warning = (unsolved ? unsolved_warning(system, result) : "") + warning_for(result, condition);
  while (!warning.empty() && warning.back() == ' ') warning.pop_back();
  return {method,
          system,
          result,
          time_s,
          has_answer,
          method.starts_with("gauss-seidel"),
          has_answer ? linalg::relative_residual(system.A, system.b, result.x) : nan,
          has_answer && system.exact_solution ? linalg::forward_error(result.x, *system.exact_solution) : nan,
          condition,
          warning};
}

nlohmann::ordered_json json_report(const SolveReport& report) {
  nlohmann::ordered_json out = {
      {"method", report.method},
      {"n", report.system.A.rows()},
      {"x", nlohmann::ordered_json::array()},
      {"status", std::string(to_string(report.result.status))},
      {"iterations", report.result.iterations},
      {"relative_residual", number_or_null(report.relative_residual)},
      {"condition_estimate", number_or_null(report.condition)},
      {"time_s", report.time_s},
      {"warning", report.warning.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(report.warning)}};
  for (double value : report.result.x) out["x"].push_back(number_or_null(value));
  if (report.system.exact_solution) out["forward_error"] = number_or_null(report.forward_error);
  if (report.method.starts_with("gepp")) out["growth_factor"] = number_or_null(report.result.growth_factor);
  if (report.iterative) out["step_inf"] = number_or_null(report.result.step_norm);
  return out;
}

void print_csv_report(std::ostream& out, const SolveReport& report) {
  out << "method,n,status,iterations,relative_residual,forward_error,growth_factor,condition_estimate,time_s";
  for (Eigen::Index i = 0; i < report.result.x.size(); ++i) out << ",x" << i + 1;
  out << '\n'
      << fmt::format("{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", report.method, report.system.A.rows(),
                     to_string(report.result.status), report.result.iterations, report.relative_residual,
                     report.forward_error, report.result.growth_factor, report.condition, report.time_s);
  for (double value : report.result.x) out << fmt::format(",{:.17g}", value);
  out << '\n';
}

void print_text_report(std::ostream& out, const SolveReport& report) {
  const DynamicResult& result = report.result;
  const char* counted = report.iterative ? " sweeps" : (report.method.starts_with("gepp") ? " pivot columns" : "");
  out << fmt::format("method             {} - {}\n", report.method, describe_linear_method(report.method))
      << fmt::format("system             {}\n", report.system.description)
      << fmt::format("status             {}\n", to_string(result.status));
  if (report.has_answer) {
    out << fmt::format("x                  {}\n", vector_text(result.x));
  } else {
    out << "x                  (none: the method did not produce a solution)\n";
  }
  out << fmt::format("iterations         {}{}\n", result.iterations, counted);
  if (report.has_answer) {
    out << fmt::format("relative residual  {:.3g}   (||b - A x|| / (||A|| ||x||))\n", report.relative_residual);
  }
  if (std::isfinite(report.forward_error)) out << fmt::format("forward error      {:.3g}\n", report.forward_error);
  if (std::isfinite(result.growth_factor)) out << fmt::format("growth factor      {:.4g}\n", result.growth_factor);
  out << fmt::format("condition estimate {:.3g}   (1-norm)\n", report.condition)
      << fmt::format("time               {:.3g} s\n", report.time_s);
  if (!report.warning.empty()) out << "WARNING            " << report.warning << '\n';
}

}  // namespace

SolveLinearCommand::SolveLinearCommand(CLI::App& solve) {
  command_ = solve.add_subcommand("linear", "Solve one linear system A x = b");
  command_->add_option("--method", method_, "Linear method")
      ->required()
      ->check(CLI::IsMember(linear_method_names()));
  auto* generate =
      command_->add_option("--generate", generate_, "Generated system KIND:N, KIND one of: random, hilbert, "
                                                    "wilkinson, diag-dominant, gs-diverge, singular");
  auto* matrix = command_->add_option("--matrix", matrix_file_, "Matrix file: rows of numbers, '#' comments");
  command_->add_option("--rhs", rhs_file_, "Right-hand side file (one row or one column)")->needs(matrix);
  command_->add_option("--seed", seed_, "Seed for random generators (default 1)");
  generate->excludes(matrix);
  add_common_options(*command_, common_);
}

int SolveLinearCommand::run() const {
  // 1. Every flag checked against the method before any work (docs/cli.md, "Which flags apply where").
  const CommonOptions common = checked_common_options(common_, "solve linear");
  const bool elimination = method_.starts_with("gepp"), iterative = method_.starts_with("gauss-seidel");
  const bool closed_form = method_ == "inverse2x2";
  const std::string hand_written = "the hand-written methods (gepp, gepp-no-pivot, gauss-seidel, gauss-seidel-plain)";
  const std::string traced = "the hand-written methods (gepp, gepp-no-pivot, gauss-seidel, gauss-seidel-plain, inverse2x2)";
  require_applies(given(common, "--trace"), elimination || iterative || closed_form, "--trace", traced);
  require_applies(given(common, "--step"), elimination || iterative || closed_form, "--step", traced);
  require_applies(given(common, "--tol"), elimination || iterative, "--tol", hand_written);
  require_applies(given(common, "--max-iter"), iterative, "--max-iter", "gauss-seidel and gauss-seidel-plain");
  require_applies(given(*command_, "--seed"), !generate_.empty(), "--seed", "--generate");
  if (generate_.empty() && matrix_file_.empty()) throw std::invalid_argument("give --generate KIND:N or --matrix FILE");
  const LoadedSystem system = generate_.empty() ? file_system(matrix_file_, rhs_file_) : generated_system(generate_, seed_);

  // 2. Solve, traced: text and CSV traces go to stderr as the solve runs; JSON traces are collected
  // for the "trace" array (and shown on stderr too with --step). The time leaves out the pauses.
  // With --step the steps are shown on stderr in every format, so that each pause follows one.
  std::ostream* trace_stream = common.trace && (common.step || common.format != Format::json) ? &std::cerr : nullptr;
  StepPause pause(common.step);
  EliminationTracer elimination_tracer(trace_stream, &pause);
  SweepTracer sweep_tracer(trace_stream, &pause);
  ClosedFormTracer closed_form_tracer(trace_stream, &pause);
  LinearTracers tracers;
  if (common.trace) tracers = {&elimination_tracer, &sweep_tracer, &closed_form_tracer};
  const auto& records = [&]() -> const nlohmann::ordered_json& {
    if (closed_form) return closed_form_tracer.records();
    return iterative ? sweep_tracer.records() : elimination_tracer.records();
  };

  const LinearSettings settings{common.tolerance, common.max_iterations};
  const auto begin = std::chrono::steady_clock::now();
  const DynamicResult result = run_linear_method(method_, system.A, system.b, settings, tracers);
  if (pause.stopped()) return report_stopped(common, {{"method", method_}, {"n", system.A.rows()}}, records());
  const double time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() - pause.seconds_waited();

  const SolveReport report = measure(method_, system, result, time_s);
  if (common.format == Format::json) {
    nlohmann::ordered_json out = json_report(report);
    if (common.trace) out["trace"] = records();
    std::cout << out.dump(2) << '\n';
  } else if (common.format == Format::csv) {
    print_csv_report(std::cout, report);
  } else {
    print_text_report(std::cout, report);
  }
  return exit_code_for(result.status);
}

}  // namespace numlab::cli
