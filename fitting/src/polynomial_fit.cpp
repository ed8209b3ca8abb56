#include "numlab/fitting/polynomial_fit.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>

#include "numlab/fitting/fit_quality.hpp"
#include "numlab/fitting/normal_equations.hpp"
#include "numlab/fitting/reference_fits.hpp"
#include "numlab/fitting/scaled_basis.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::fitting {

namespace {

// Joins the parts into one message, numbers with up to 3 significant digits.
template <typename... Parts>
std::string message(const Parts&... parts) {
  std::ostringstream text;
  text.precision(3);
  (text << ... << parts);
  return text.str();
}

void check_input(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  if (x.size() != y.size()) {
    throw std::invalid_argument(message("x has ", x.size(), " values but y has ", y.size()));
  }
  if (options.degree < 0) throw std::invalid_argument(message("degree must be >= 0, got ", options.degree));
  if (options.degree >= x.size()) {
    throw std::invalid_argument(message("degree ", options.degree, " needs at least ", options.degree + 1,
                                        " points, the data has ", x.size()));
  }
  linalg::require_finite(x, "x");
  linalg::require_finite(y, "y");
}

// kappa_1 of D M D with D = diag(1 / sqrt(m_kk)): M with its rows and columns scaled to unit
// diagonal. Elimination's rounding errors do not depend on such a scaling (it only rescales the
// unknowns), so this, not kappa(M), predicts the digits lost; for symmetric positive definite M it
// is within a factor n of the best diagonal scaling (van der Sluis).
double equilibrated_condition(const Eigen::MatrixXd& M) {
  const Eigen::VectorXd d = M.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
  if (!d.allFinite()) return std::numeric_limits<double>::infinity();
  return linalg::condition_estimate(d.asDiagonal() * M * d.asDiagonal());
}

// Solves the normal equations with the chosen hand-written solver.
linalg::LinearResult<Eigen::Dynamic> solve_normal_equations(const NormalEquations& system, const FitOptions& options) {
  if (options.solver == NormalSolver::gepp) {
    return linalg::GaussElimination<>().solve(system.matrix, system.rhs);
  }
  // V^T V is symmetric positive definite, so Gauss-Seidel on it converges (slowly when ill-conditioned).
  linalg::GaussSeidelOptions sweeps;
  sweeps.system = linalg::GaussSeidelOptions::System::plain;
  sweeps.tolerance = options.sweep_tolerance;
  sweeps.max_iterations = options.max_sweeps;
  return linalg::GaussSeidel<>(sweeps).solve(system.matrix, system.rhs);
}

// The status's explanation when a solve did not converge; empty otherwise.
std::string failure_warning(const linalg::LinearResult<Eigen::Dynamic>& result) {
  switch (result.status) {
    case Status::converged: return "";
    case Status::singular:
      return "Gaussian elimination met a negligible pivot: the normal matrix is singular to working precision, "
             "so there are no coefficients.";
    case Status::max_iterations:
      return message("Gauss-Seidel stopped after ", result.iterations, " sweeps without converging (last step ",
                     result.step_norm, "): the coefficients are unfinished iterates.");
    default:
      return message("The normal-equations solve ended with status ", to_string(result.status),
                     "; the coefficients are not a fit.");
  }
}

// normal and normal-scaled: V^T V b = V^T y on x itself, or on t = (x - c) / s then mapped back.
PolynomialFit normal_equations_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  const bool scaled = options.method == FitMethod::normal_scaled;
  const AffineScaling scaling = scaled ? scaling_for(x) : AffineScaling{};
  const NormalEquations system = build_normal_equations(scaled ? to_scaled(x, scaling) : x, y, options.degree);
  const linalg::LinearResult<Eigen::Dynamic> solved = solve_normal_equations(system, options);

  PolynomialFit fit;
  fit.status = solved.status;
  fit.iterations = solved.iterations;
  fit.condition_estimate = equilibrated_condition(system.matrix);
  fit.condition_unscaled = linalg::condition_estimate(system.matrix);
  fit.condition_of = scaled ? "normal matrix of the scaled variable t" : "normal matrix V^T V";
  const std::string failure = failure_warning(solved);
  if (solved.status == Status::singular || solved.status == Status::non_finite || !solved.x.allFinite()) {
    if (fit.status == Status::converged) fit.status = Status::non_finite;
    fit.warning = failure.empty() ? "The solve produced non-finite coefficients." : failure;
    return fit;
  }
  fit.coefficients = scaled ? to_original_powers(solved.x, scaling) : solved.x;
  fit.warning = failure;
  return fit;
}

PolynomialFit reference_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  const bool gsl = options.method == FitMethod::gsl;
  const ReferenceFit reference = gsl ? gsl_multifit_fit(x, y, options.degree) : eigen_qr_fit(x, y, options.degree);
  PolynomialFit fit;
  fit.iterations = 1;
  fit.coefficients = reference.coefficients;
  fit.condition_estimate = reference.condition_estimate;
  fit.condition_unscaled = reference.condition_unscaled;
  fit.condition_of = gsl ? "column-scaled Vandermonde matrix (GSL's SVD)" : "Vandermonde matrix V";
  if (!reference.coefficients.allFinite()) {
    fit.status = Status::non_finite;
    fit.coefficients.resize(0);
    fit.warning = "The solve produced non-finite coefficients.";
  } else if (reference.rank_deficient) {
    fit.status = Status::singular;
    fit.warning = "The Vandermonde matrix is rank deficient to working precision.";
  }
  return fit;
}

}  // namespace

std::string_view to_string(FitMethod method) {
  switch (method) {
    case FitMethod::normal: return "normal";
    case FitMethod::normal_scaled: return "normal-scaled";
    case FitMethod::gsl: return "gsl";
    case FitMethod::eigen_qr: return "eigen-qr";
  }
  return "unknown";
}

std::string_view to_string(NormalSolver solver) {
  return solver == NormalSolver::gepp ? "gepp" : "gauss-seidel";
}

FitMethod fit_method_from_string(std::string_view name) {
  for (FitMethod method : {FitMethod::normal, FitMethod::normal_scaled, FitMethod::gsl, FitMethod::eigen_qr}) {
    if (name == to_string(method)) return method;
  }
  throw std::invalid_argument(message("unknown fit method '", name, "' (known: normal, normal-scaled, gsl, eigen-qr)"));
}

NormalSolver normal_solver_from_string(std::string_view name) {
  if (name == "gepp") return NormalSolver::gepp;
  if (name == "gauss-seidel") return NormalSolver::gauss_seidel;
  throw std::invalid_argument(
      message("unknown linear solver '", name, "' for the normal equations (known: gepp, gauss-seidel)"));
}

PolynomialFit fit_polynomial(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  check_input(x, y, options);
  const bool normal = options.method == FitMethod::normal || options.method == FitMethod::normal_scaled;
  PolynomialFit fit = normal ? normal_equations_fit(x, y, options) : reference_fit(x, y, options);
  fit.method = options.method;
  fit.degree = options.degree;
  if (fit.coefficients.size() > 0) {
    const FitStatistics statistics = fit_statistics(x, y, fit.coefficients);
    fit.residual_sd = statistics.residual_sd;
    fit.r_squared = statistics.r_squared;
  }
  // A failed solve's explanation first, then the conditioning warning, which applies even when
  // the solve itself "converged".
  const std::string conditioning = conditioning_warning(fit.condition_estimate, fit.condition_of);
  if (!conditioning.empty()) fit.warning = fit.warning.empty() ? conditioning : fit.warning + " " + conditioning;
  return fit;
}

double evaluate_polynomial(const Eigen::VectorXd& coefficients, double x) {
  double value = 0.0;
  for (Eigen::Index k = coefficients.size() - 1; k >= 0; --k) value = value * x + coefficients(k);
  return value;
}

}  // namespace numlab::fitting
