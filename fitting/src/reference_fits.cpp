#include "numlab/fitting/reference_fits.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <memory>

#include "numlab/fitting/scaled_basis.hpp"

namespace numlab::fitting {

namespace {

struct GslDeleter {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
  void operator()(gsl_multifit_linear_workspace* w) const { gsl_multifit_linear_free(w); }
};
template <typename T>
using GslPointer = std::unique_ptr<T, GslDeleter>;

template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> vandermonde_of(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x,
                                                                      int degree) {
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> V(x.size(), degree + 1);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Scalar power = 1;
    for (int k = 0; k <= degree; ++k, power *= x(i)) V(i, k) = power;
  }
  return V;
}

}  // namespace

// sigma_max / sigma_min, infinite when sigma_min is 0.
double two_norm_condition(const Eigen::MatrixXd& A) {
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(A).singularValues();
  const double smallest = sigma(sigma.size() - 1);
  return smallest > 0.0 ? sigma(0) / smallest : std::numeric_limits<double>::infinity();
}

// A with each column divided by its 2-norm.
Eigen::MatrixXd unit_columns(const Eigen::MatrixXd& A) {
  Eigen::MatrixXd scaled = A;
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    const double norm = A.col(j).norm();
    if (norm > 0.0) scaled.col(j) /= norm;
  }
  return scaled;
}

Eigen::MatrixXd vandermonde(const Eigen::VectorXd& x, int degree) { return vandermonde_of<double>(x, degree); }

ReferenceFit gsl_multifit_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  gsl_set_error_handler_off();  // GSL's default handler aborts; a failed fit is reported instead
  const auto n = static_cast<std::size_t>(x.size());
  const auto p = static_cast<std::size_t>(degree + 1);
  const Eigen::MatrixXd V = vandermonde(x, degree);
  GslPointer<gsl_matrix> X(gsl_matrix_alloc(n, p));
  GslPointer<gsl_matrix> covariance(gsl_matrix_alloc(p, p));
  GslPointer<gsl_vector> observations(gsl_vector_alloc(n));
  GslPointer<gsl_vector> c(gsl_vector_alloc(p));
  GslPointer<gsl_multifit_linear_workspace> work(gsl_multifit_linear_alloc(n, p));
  for (std::size_t i = 0; i < n; ++i) {
    gsl_vector_set(observations.get(), i, y(static_cast<Eigen::Index>(i)));
    for (std::size_t k = 0; k < p; ++k) {
      gsl_matrix_set(X.get(), i, k, V(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)));
    }
  }
  double chi_squared = 0.0;
  const int error = gsl_multifit_linear(X.get(), observations.get(), c.get(), covariance.get(), &chi_squared, work.get());
  ReferenceFit fit;
  fit.coefficients.resize(static_cast<Eigen::Index>(p));
  for (std::size_t k = 0; k < p; ++k) fit.coefficients(static_cast<Eigen::Index>(k)) = gsl_vector_get(c.get(), k);
  const double rcond = gsl_multifit_linear_rcond(work.get());
  fit.condition_estimate = rcond > 0.0 ? 1.0 / rcond : std::numeric_limits<double>::infinity();
  fit.condition_unscaled = two_norm_condition(V);
  fit.rank_deficient = error != GSL_SUCCESS || !(rcond > 0.0);
  return fit;
}

ReferenceFit eigen_qr_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  const Eigen::MatrixXd V = vandermonde(x, degree);
  ReferenceFit fit;
  fit.coefficients = Eigen::HouseholderQR<Eigen::MatrixXd>(V).solve(y);
  fit.condition_estimate = two_norm_condition(unit_columns(V));
  fit.condition_unscaled = two_norm_condition(V);
  fit.rank_deficient = !std::isfinite(fit.condition_unscaled);
  return fit;
}

Eigen::VectorXd extended_precision_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  using LongVector = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  using LongMatrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  const AffineScaling scaling = scaling_for(x);
  const long double centre = scaling.centre;
  const long double scale = scaling.scale;
  // 1. t = (x - c) / s in long double; 2. QR of the Vandermonde matrix in t; 3. map back.
  const LongVector t = (x.cast<long double>().array() - centre) / scale;
  const LongMatrix V = vandermonde_of<long double>(t, degree);
  const LongVector a = Eigen::HouseholderQR<LongMatrix>(V).solve(LongVector(y.cast<long double>()));
  return to_original_powers<long double>(a, centre, scale).cast<double>();
}

}  // namespace numlab::fitting
