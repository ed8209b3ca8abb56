#include "commands/fit_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include "output/fit_charts.hpp"
#include "scenes/foot_path.hpp"
#include "numlab/fitting/data_set.hpp"
#include "numlab/fitting/log_relative_error.hpp"
#include "numlab/fitting/normal_equations.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/fitting/scaled_basis.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

using fitting::FitMethod;

bool uses_normal_equations(FitMethod method) {
  return method == FitMethod::normal || method == FitMethod::normal_scaled;
}

// The certified parameters, when the data file carries them for this degree.
std::optional<Eigen::VectorXd> certified_for(const fitting::DataSet& data, int degree) {
  if (!data.certified || static_cast<int>(data.certified->parameters.size()) != degree + 1) return std::nullopt;
  return Eigen::Map<const Eigen::VectorXd>(data.certified->parameters.data(), degree + 1);
}

std::string method_description(const fitting::FitOptions& options, const fitting::DataSet& data) {
  const std::string solver = options.solver == fitting::NormalSolver::gepp ? "GEPP" : "Gauss-Seidel";
  switch (options.method) {
    case FitMethod::normal: return "normal equations (V^T V) b = V^T y, solved by " + solver;
    case FitMethod::normal_scaled: {
      const fitting::AffineScaling s = fitting::scaling_for(data.x);
      return fmt::format("normal equations in t = (x - {:.6g}) / {:.6g}, solved by {}, mapped back to powers of x",
                         s.centre, s.scale, solver);
    }
    case FitMethod::gsl: return "gsl_multifit_linear (SVD of the column-scaled Vandermonde matrix)";
    case FitMethod::eigen_qr: return "Eigen HouseholderQR of the Vandermonde matrix";
  }
  return "";
}

// --trace: the system the normal-equation methods build (the fit's first step), before it is solved.
void print_normal_equations(std::ostream& out, const fitting::NormalEquations& system, const fitting::FitOptions& options) {
  const bool scaled = options.method == FitMethod::normal_scaled;
  out << (scaled ? "normal equations in t (power sums | moments):\n" : "normal equations (power sums | moments):\n");
  for (Eigen::Index i = 0; i < system.matrix.rows(); ++i) {
    out << "  ";
    for (Eigen::Index j = 0; j < system.matrix.cols(); ++j) out << fmt::format("{:>12.5g} ", system.matrix(i, j));
    out << fmt::format("| {:>12.5g}\n", system.rhs(i));
  }
}

struct FitRun {
  const fitting::DataSet& data;
  const fitting::FitOptions& options;
  const fitting::PolynomialFit& fit;
  std::optional<Eigen::VectorXd> certified;
  double time_s;
};

nlohmann::ordered_json json_report(const FitRun& run) {
  const fitting::PolynomialFit& fit = run.fit;
  nlohmann::ordered_json coefficients = nlohmann::ordered_json::array();
  for (Eigen::Index k = 0; k < fit.coefficients.size(); ++k) coefficients.push_back(number_or_null(fit.coefficients(k)));
  const bool has_fit = fit.coefficients.size() > 0;
  nlohmann::ordered_json out = {
      {"method", std::string(to_string(fit.method))},
      {"linear", uses_normal_equations(fit.method) ? nlohmann::ordered_json(std::string(to_string(run.options.solver)))
                                                   : nlohmann::ordered_json()},
      {"data", run.data.name},
      {"n", run.data.x.size()},
      {"degree", fit.degree},
      {"coefficients", has_fit ? coefficients : nlohmann::ordered_json()},
      {"status", std::string(to_string(fit.status))},
      {"iterations", fit.iterations},
      {"residual_sd", has_fit ? number_or_null(fit.residual_sd) : nlohmann::ordered_json()},
      {"r_squared", has_fit ? number_or_null(fit.r_squared) : nlohmann::ordered_json()},
      {"condition_estimate", number_or_null(fit.condition_estimate)},
      {"condition_unscaled", number_or_null(fit.condition_unscaled)},
      {"condition_of", fit.condition_of},
      {"condition_measure", fit.condition_measure},
      {"warning", fit.warning.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(fit.warning)},
      {"time_s", run.time_s}};
  if (run.certified) {
    nlohmann::ordered_json lre = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < run.certified->size() && has_fit; ++k) {
      lre.push_back(fitting::log_relative_error(fit.coefficients(k), (*run.certified)(k)));
    }
    out["certified"] = {{"parameters", std::vector<double>(run.certified->data(), run.certified->data() + run.certified->size())},
                        {"lre", lre},
                        {"min_lre", has_fit ? fitting::min_log_relative_error(fit.coefficients, *run.certified) : 0.0}};
  }
  return out;
}

Table coefficient_table(const FitRun& run) {
  std::vector<std::string> header = {"power", "coefficient"};
  if (run.certified) header.insert(header.end(), {"certified", "LRE (digits)"});
  Table table(header);
  for (Eigen::Index k = 0; k < run.fit.coefficients.size(); ++k) {
    std::vector<std::string> row = {std::to_string(k), fmt::format("{:.15g}", run.fit.coefficients(k))};
    if (run.certified) {
      row.push_back(fmt::format("{:.15g}", (*run.certified)(k)));
      row.push_back(fmt::format("{:.1f}", fitting::log_relative_error(run.fit.coefficients(k), (*run.certified)(k))));
    }
    table.add_row(row);
  }
  return table;
}

void print_text(std::ostream& out, const FitRun& run) {
  const fitting::PolynomialFit& fit = run.fit;
  out << fmt::format("fit {} ({} points), degree {}: {}\n", run.data.name, run.data.x.size(), fit.degree,
                     method_description(run.options, run.data));
  out << fmt::format("status {} after {} {}; time {:.3g} s\n", to_string(fit.status), fit.iterations,
                     run.options.solver == fitting::NormalSolver::gauss_seidel && uses_normal_equations(fit.method)
                         ? "sweeps" : "steps",
                     run.time_s);
  out << fmt::format("condition of the {}: {:.3g} ({}; {:.3g} as it stands)\n", fit.condition_of,
                     fit.condition_estimate, fit.condition_measure, fit.condition_unscaled);
  if (!fit.warning.empty()) out << "WARNING: " << fit.warning << '\n';
  if (fit.coefficients.size() == 0) {
    out << "no coefficients.\n";
    return;
  }
  const std::string r_squared = std::isnan(fit.r_squared) ? "undefined (every y is equal)" : fmt::format("{:.9g}", fit.r_squared);
  out << fmt::format("residual sd {:.6g}; R^2 {}\n", fit.residual_sd, r_squared);
  out << (fit.warning.empty() ? "coefficients, increasing powers of x:\n"
                              : "coefficients, increasing powers of x (NOT to be trusted, see the warning):\n");
  coefficient_table(run).print(out);
  if (run.certified) {
    out << fmt::format("fewest correct digits against NIST's certified values: {:.1f}\n",
                       fitting::min_log_relative_error(fit.coefficients, *run.certified));
  }
}

}  // namespace

FitCommand::FitCommand(CLI::App& app) {
  command_ = app.add_subcommand("fit", "Least-squares polynomial fit: normal equations against GSL and Eigen QR");
  auto* data = command_->add_option("--data", data_file_, "CSV with x and y columns, or a NIST StRD .dat file");
  auto* foot = command_->add_option("--foot-path", foot_path_,
                                    "Fit an arc of the Jansen foot's path instead: upper or lower");
  data->excludes(foot);
  command_->add_option("--degree", degree_, "Polynomial degree D (0 <= D < number of points)")->required();
  command_->add_option("--method", method_, "normal (default), normal-scaled, gsl or eigen-qr");
  command_->add_option("--linear", linear_, "Solver for the normal equations: gepp (default) or gauss-seidel");
  command_->add_option("--chart", chart_, "Draw the data and the fitted curve (FILE.svg or FILE.png)");
  add_common_options(*command_, common_);
}

int FitCommand::run() const {
  // 1. Check everything the user gave before doing any work (docs/cli.md, "Which flags apply where").
  const CommonOptions common = checked_common_options(common_, "fit");
  if (data_file_.empty() == foot_path_.empty()) throw std::invalid_argument("fit: give --data FILE or --foot-path ARC");
  fitting::FitOptions options;
  options.method = fitting::fit_method_from_string(method_);
  options.solver = fitting::normal_solver_from_string(linear_);
  options.degree = degree_;
  const bool normal = uses_normal_equations(options.method);
  const bool sweeps = normal && options.solver == fitting::NormalSolver::gauss_seidel;
  require_applies(given(common, "--trace"), normal, "--trace", "--method normal and normal-scaled");
  require_applies(given(*command_, "--linear"), normal, "--linear", "--method normal and normal-scaled");
  require_applies(given(common, "--tol"), sweeps, "--tol", "--linear gauss-seidel (its step test)");
  require_applies(given(common, "--max-iter"), sweeps, "--max-iter", "--linear gauss-seidel (its sweep limit)");
  if (common.tolerance) options.sweep_tolerance = *common.tolerance;
  if (common.max_iterations) options.max_sweeps = *common.max_iterations;
  require_applies(given(common, "--out"), !chart_.empty(), "--out", "--chart (the folder for the files it writes)");
  if (given(*command_, "--chart") && chart_.empty()) throw std::invalid_argument("--chart needs a file name");
  const std::string chart_path = output_path(common, chart_);
  const std::optional<ChartFiles> chart = chart_.empty() ? std::nullopt : std::optional(chart_files(chart_path));
  if (chart) check_outputs(planned_files(*chart, "--chart"), data_file_.empty() ? std::vector<std::string>{} : std::vector{data_file_});
  fitting::DataSet data;
  if (!data_file_.empty()) {
    data = fitting::read_data_file(data_file_);
  } else {
    const fitting::PathArc arc = jansen_foot_arc(foot_path_);
    data = {"jansen-foot-" + foot_path_, arc.x, arc.y, std::nullopt};
  }

  // 2. Fit, timed.
  const auto start = std::chrono::steady_clock::now();
  fitting::PolynomialFitter fitter;
  const fitting::PolynomialFit fit = fitter.solve(data.x, data.y, options);
  const double time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const FitRun run{data, options, fit, certified_for(data, options.degree), time_s};

  // 3. The chart first: a chart that cannot be written is an error (exit 2) with nothing on stdout.
  const bool drawn = chart && fit.coefficients.size() > 0;
  if (drawn) {
    draw_fit_chart(*chart, fmt::format("{}: degree-{} fit ({})", data.name, fit.degree, to_string(fit.method)),
                   {{data.name, data.x, data.y, fit.coefficients}});
  }

  // 4. Report.
  if (common.trace && normal) {
    print_normal_equations(common.format == Format::text ? std::cout : std::cerr, fitter.normal_equations(), options);
  }
  if (common.format == Format::json) {
    std::cout << json_report(run).dump(2) << '\n';
  } else if (common.format == Format::csv) {
    std::cout << coefficient_table(run).csv();
  } else {
    print_text(std::cout, run);
  }
  if (drawn && common.format == Format::text) std::cout << "chart: " << chart->chart << '\n';
  return exit_code_for(fit.status);
}

}  // namespace numlab::cli
