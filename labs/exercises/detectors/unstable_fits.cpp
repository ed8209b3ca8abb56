#include "exercises/detectors/unstable_fits.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include <memory>
#include <stdexcept>

#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/fitting/reference_fits.hpp"

namespace numlab::exercises::detectors {

namespace {

struct GslFree {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
};
template <typename T>
using Gsl = std::unique_ptr<T, GslFree>;

}  // namespace

Eigen::VectorXd unscaled_svd_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  const Eigen::MatrixXd V = fitting::vandermonde(x, degree);
  const auto m = static_cast<std::size_t>(V.rows()), n = static_cast<std::size_t>(V.cols());
  if (m < n || n == 0 || y.size() != V.rows()) return {};
  gsl_set_error_handler_off();  // GSL's default handler aborts; a failed SVD gives no replay
  Gsl<gsl_matrix> U(gsl_matrix_alloc(m, n)), W(gsl_matrix_alloc(n, n));
  Gsl<gsl_vector> singular(gsl_vector_alloc(n)), work(gsl_vector_alloc(n)), rhs(gsl_vector_alloc(m)),
      solution(gsl_vector_alloc(n));
  for (std::size_t i = 0; i < m; ++i) {
    gsl_vector_set(rhs.get(), i, y(static_cast<Eigen::Index>(i)));
    for (std::size_t k = 0; k < n; ++k) {
      gsl_matrix_set(U.get(), i, k, V(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)));
    }
  }
  if (gsl_linalg_SV_decomp(U.get(), W.get(), singular.get(), work.get()) != GSL_SUCCESS) return {};
  if (gsl_linalg_SV_solve(U.get(), W.get(), singular.get(), rhs.get(), solution.get()) != GSL_SUCCESS) return {};
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) b(static_cast<Eigen::Index>(k)) = gsl_vector_get(solution.get(), k);
  return b;
}

Eigen::VectorXd power_sum_normal_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  fitting::FitOptions options;
  options.degree = degree;
  options.method = fitting::FitMethod::normal;
  try {
    const fitting::PolynomialFit fit = fitting::fit_polynomial(x, y, options);
    if (fit.status != Status::converged) return {};
    return fit.coefficients;
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace numlab::exercises::detectors
