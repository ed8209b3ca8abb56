#include "numlab/fitting/polynomial_fit.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "numlab/fitting/fit_quality.hpp"
#include "numlab/fitting/least_squares_check.hpp"
#include "numlab/fitting/reference_fits.hpp"
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

// The first entry of the normal equations [V^T V | V^T y] that overflowed (a power sum of large
// values to a high power), with its numbers; empty when every entry is finite. `variable`: x or t.
std::string overflow_in(const NormalEquations& system, const char* variable) {
  const Eigen::MatrixXd& M = system.matrix;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    for (Eigen::Index j = 0; j < M.cols(); ++j) {
      if (std::isfinite(M(i, j))) continue;
      return message("The normal equations overflow: entry (", i + 1, ", ", j + 1, ") of V^T V, the sum of ", variable,
                     "^", i + j, " over the points, is ", M(i, j), ", so there are no coefficients.");
    }
  }
  for (Eigen::Index i = 0; i < system.rhs.size(); ++i) {
    if (std::isfinite(system.rhs(i))) continue;
    return message("The normal equations overflow: entry ", i + 1, " of V^T y, the sum of ", variable, "^", i,
                   " y over the points, is ", system.rhs(i), ", so there are no coefficients.");
  }
  return "";
}

bool is_normal_equations(FitMethod method) {
  return method == FitMethod::normal || method == FitMethod::normal_scaled;
}

// Whether s^D or s^-D, the factors between powers of t and powers of x, leave the normal doubles.
bool powers_beyond_doubles(double scale, int degree) {
  return std::abs(static_cast<double>(std::ilogb(scale)) * degree) >= std::numeric_limits<double>::max_exponent - 2;
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

void PolynomialFitter::start(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  check_input(x, y, options);
  options_ = options;
  data_x_ = x;
  data_y_ = y;
  scaling_ = AffineScaling{};
  system_ = NormalEquations{};
  coefficients_.resize(0);
  fit_ = PolynomialFit{};
  fit_.method = options.method;
  fit_.degree = options.degree;
  next_ = is_normal_equations(options.method) ? FitStage::build_system : FitStage::solve_system;
  steps_ = 0;
  status_ = Status::running;
  running_ = true;
  stopped_ = false;
}

bool PolynomialFitter::step() {
  if (!running_) return false;
  const FitStage stage = next_;
  switch (stage) {
    case FitStage::build_system: build_system(); break;
    case FitStage::solve_system: solve_system(); break;
    case FitStage::finish_fit: finish_fit(); break;
  }
  ++steps_;
  if (observer_ != nullptr && observer_->on_step(*this, {stage}) == StepControl::stop && running_) {
    running_ = false;  // the observer ended the run: no verdict
    stopped_ = true;
  }
  return running_;
}

PolynomialFit PolynomialFitter::solve(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  start(x, y, options);
  while (step()) {
  }
  return fit_;
}

// 1. The normal equations V^T V b = V^T y, on x itself or on t = (x - c) / s.
void PolynomialFitter::build_system() {
  const bool scaled = options_.method == FitMethod::normal_scaled;
  if (scaled) scaling_ = scaling_for(data_x_);
  system_ = build_normal_equations(scaled ? to_scaled(data_x_, scaling_) : data_x_, data_y_, options_.degree);
  next_ = FitStage::solve_system;
}

// 2. The solve: the normal equations by the chosen hand-written solver, or the reference method.
void PolynomialFitter::solve_system() {
  next_ = FitStage::finish_fit;
  if (!is_normal_equations(options_.method)) {
    const bool gsl = options_.method == FitMethod::gsl;
    const ReferenceFit reference =
        gsl ? gsl_multifit_fit(data_x_, data_y_, options_.degree) : eigen_qr_fit(data_x_, data_y_, options_.degree);
    fit_.iterations = 1;
    coefficients_ = reference.coefficients;
    fit_.condition_estimate = reference.condition_estimate;
    fit_.condition_unscaled = reference.condition_unscaled;
    fit_.condition_of = gsl ? "column-scaled Vandermonde matrix (GSL's SVD)" : "Vandermonde matrix V";
    fit_.condition_measure = gsl ? "1/rcond of GSL's SVD, columns balanced by powers of two"
                                 : "kappa_2, columns scaled to unit 2-norm";
    if (!reference.coefficients.allFinite()) {
      fit_.status = Status::non_finite;
      coefficients_.resize(0);
      fit_.warning = "The solve produced non-finite coefficients.";
    } else if (reference.rank_deficient) {
      fit_.status = Status::singular;
      fit_.warning = "The Vandermonde matrix is rank deficient to working precision.";
    }
    return;
  }

  const bool scaled = options_.method == FitMethod::normal_scaled;
  fit_.condition_of = scaled ? "normal matrix of the scaled variable t" : "normal matrix V^T V";
  fit_.condition_measure = "kappa_1 estimate, rows and columns scaled to a unit diagonal";
  const bool matrix_finite = system_.matrix.allFinite();
  fit_.condition_estimate = matrix_finite ? equilibrated_condition(system_.matrix) : std::numeric_limits<double>::infinity();
  fit_.condition_unscaled = matrix_finite ? linalg::condition_estimate(system_.matrix) : fit_.condition_estimate;
  // Overflowed sums are the method's failure on this data, not bad input: a status and the numbers.
  if (const std::string overflow = overflow_in(system_, scaled ? "t" : "x"); !overflow.empty()) {
    fit_.status = Status::non_finite;
    fit_.warning = overflow;
    return;  // no coefficients
  }
  const linalg::LinearResult<Eigen::Dynamic> solved = solve_normal_equations(system_, options_);
  fit_.status = solved.status;
  fit_.iterations = solved.iterations;
  const std::string failure = failure_warning(solved);
  coefficients_ = solved.x;
  if (solved.status == Status::singular || solved.status == Status::non_finite || !solved.x.allFinite()) {
    if (fit_.status == Status::converged) fit_.status = Status::non_finite;
    fit_.warning = failure.empty() ? "The solve produced non-finite coefficients." : failure;
    coefficients_.resize(0);  // no coefficients to map back
    return;
  }
  fit_.warning = failure;
}

// 3. The coefficients in powers of x, the residual statistics, and the warnings.
void PolynomialFitter::finish_fit() {
  const bool scaled = options_.method == FitMethod::normal_scaled && coefficients_.size() > 0;
  const Eigen::VectorXd in_t = scaled ? coefficients_ : Eigen::VectorXd();
  if (scaled) coefficients_ = to_original_powers(coefficients_, scaling_);
  fit_.coefficients = coefficients_;
  if (fit_.coefficients.size() > 0) {
    const FitStatistics statistics = fit_statistics(data_x_, data_y_, fit_.coefficients);
    fit_.residual_sd = statistics.residual_sd;
    fit_.r_squared = statistics.r_squared;
  }
  // The least-squares check (least_squares_check.hpp): converged only when the coefficients
  // reported are a least-squares fit to within rounding.
  if (fit_.status == Status::converged && fit_.coefficients.size() > 0) {
    const LeastSquaresCheck check = check_least_squares(data_x_, data_y_, fit_.coefficients, in_t, fit_.r_squared);
    if (!check.passed()) {
      const bool beyond = !check.finite || (scaled && powers_beyond_doubles(scaling_.scale, options_.degree));
      fit_.status = beyond ? Status::non_finite : Status::no_progress;
      std::string why = beyond ? message("The coefficients in powers of x are beyond the doubles (s = ", scaling_.scale,
                                         ", s^", options_.degree, " is not a normal double), so p(x) is not the fit found.")
                               : message("The coefficients fail the least-squares check: the residual is not "
                                         "orthogonal to power ", check.worst_power, " (", check.worst_ratio,
                                         " times what rounding explains), R^2 = ", fit_.r_squared, ".");
      fit_.warning = fit_.warning.empty() ? why : fit_.warning + " " + why;
    }
  }
  // A failed solve's explanation first, then the conditioning warning, which applies even when
  // the solve itself "converged".
  const std::string conditioning = conditioning_warning(fit_.condition_estimate, fit_.condition_of);
  if (!conditioning.empty()) fit_.warning = fit_.warning.empty() ? conditioning : fit_.warning + " " + conditioning;
  status_ = fit_.status;
  running_ = false;
}

PolynomialFit fit_polynomial(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const FitOptions& options) {
  return PolynomialFitter().solve(x, y, options);
}

double evaluate_polynomial(const Eigen::VectorXd& coefficients, double x) {
  double value = 0.0;
  for (Eigen::Index k = coefficients.size() - 1; k >= 0; --k) value = value * x + coefficients(k);
  return value;
}

}  // namespace numlab::fitting
