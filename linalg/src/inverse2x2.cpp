#include "numlab/linalg/inverse2x2.hpp"

#include <cmath>
#include <limits>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::linalg {

Inverse2x2 inverse2x2(const Eigen::Matrix2d& A) {
  require_finite(A, "2x2 matrix");
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const double largest = A.cwiseAbs().maxCoeff();
  if (largest == 0.0) return {Eigen::Matrix2d::Constant(nan), 0.0, infinity, Status::singular};

  // Scale by a power of two near 1/max|a_ij| (exact in binary floating point).
  int exponent = 0;
  std::frexp(largest, &exponent);
  const Eigen::Matrix2d scaled = A * std::ldexp(1.0, -exponent);

  // Determinant of the scaled matrix, and its size relative to ||A||_F^2.
  const double a = scaled(0, 0), b = scaled(0, 1), c = scaled(1, 0), d = scaled(1, 1);
  const double scaled_determinant = a * d - b * c;
  const double determinant = std::ldexp(scaled_determinant, 2 * exponent);
  const double frobenius_squared = scaled.squaredNorm();

  if (std::abs(scaled_determinant) <= std::numeric_limits<double>::epsilon() * frobenius_squared) {
    const double ratio = frobenius_squared / std::abs(scaled_determinant);  // infinity when det = 0
    const double kappa = std::isfinite(ratio) ? 0.5 * (ratio + std::sqrt(ratio * ratio - 4.0)) : infinity;
    return {Eigen::Matrix2d::Constant(nan), determinant, kappa, Status::singular};
  }

  // kappa + 1/kappa = ||A||_F^2 / |det A|  =>  kappa = (r + sqrt(r^2 - 4)) / 2.
  const double ratio = frobenius_squared / std::abs(scaled_determinant);
  const double kappa = 0.5 * (ratio + std::sqrt(std::max(ratio * ratio - 4.0, 0.0)));

  // Closed form: (1/det) [d -b; -c a], then undo the scaling.
  Eigen::Matrix2d inverse;
  inverse << d, -b, -c, a;
  inverse *= std::ldexp(1.0 / scaled_determinant, -exponent);
  return {inverse, determinant, kappa, Status::converged};
}

LinearResult<2> solve2x2(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) {
  require_finite(b, "right-hand side");
  const Inverse2x2 closed_form = inverse2x2(A);
  LinearResult<2> result;
  result.status = closed_form.status;
  result.iterations = 1;
  result.x = closed_form.inverse * b;
  if (result.status == Status::converged) {
    if (!result.x.allFinite()) {
      result.status = Status::non_finite;
    } else {
      result.residual_norm = residual_inf_norm(A, b, result.x);
    }
  }
  return result;
}

}  // namespace numlab::linalg
