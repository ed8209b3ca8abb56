#include "numlab/fitting/least_squares_check.hpp"

#include <cmath>
#include <limits>

#include "numlab/fitting/polynomial_fit.hpp"

namespace numlab::fitting {

LeastSquaresCheck check_least_squares(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                      const Eigen::VectorXd& coefficients, const Eigen::VectorXd& scaled_coefficients,
                                      double r_squared) {
  LeastSquaresCheck check;
  const Eigen::Index m = x.size(), powers = coefficients.size();
  const Eigen::VectorXd magnitudes = coefficients.cwiseAbs();
  Eigen::VectorXd r(m), size(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    r(i) = y(i) - evaluate_polynomial(coefficients, x(i));
    size(i) = std::abs(y(i)) + evaluate_polynomial(magnitudes, std::abs(x(i))) + std::abs(r(i));  // |y| + h + |r|
  }
  if (!coefficients.allFinite() || !r.allFinite() || !size.allFinite()) {
    check.finite = false;
    return check;
  }
  const AffineScaling scaling = scaling_for(x);
  const Eigen::VectorXd t = to_scaled(x, scaling);
  const Eigen::VectorXd g = (std::abs(scaling.centre) + x.cwiseAbs().array()) / scaling.scale;  // g_i >= |t_i|
  if (scaled_coefficients.size() > 0) {
    for (Eigen::Index i = 0; i < m; ++i) size(i) += evaluate_polynomial(scaled_coefficients.cwiseAbs(), g(i));
  }
  const double gamma = 10.0 * static_cast<double>(m * powers) * std::numeric_limits<double>::epsilon();
  Eigen::VectorXd t_power = Eigen::VectorXd::Ones(m), g_power = Eigen::VectorXd::Ones(m);
  for (Eigen::Index k = 0; k < powers; ++k) {
    const double inner = std::abs(t_power.dot(r));
    const double bound = gamma * g_power.dot(size);
    const double ratio = bound > 0.0 ? inner / bound : (inner > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    if (!(ratio <= check.worst_ratio)) {
      check.worst_ratio = ratio;
      check.worst_power = static_cast<int>(k);
    }
    t_power = t_power.cwiseProduct(t);
    g_power = g_power.cwiseProduct(g);
  }
  check.orthogonal = check.worst_ratio <= 1.0;
  // RSS <= TSS up to rounding: R^2 >= 0 less a few eps per point. NaN only when every y is equal
  // (TSS = 0, R^2 undefined); a NaN from anything else is a failure, not an undefined statistic.
  const bool all_y_equal = y.size() > 0 && (y.array() == y(0)).all();
  check.r_squared_in_range = std::isnan(r_squared) ? all_y_equal : (r_squared >= -gamma && r_squared <= 1.0 + gamma);
  return check;
}

}  // namespace numlab::fitting
