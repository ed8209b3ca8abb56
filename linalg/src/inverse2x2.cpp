#include "numlab/linalg/inverse2x2.hpp"

#include <cmath>
#include <limits>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::linalg {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

using detail::inverse_of;
using detail::scaled_closed_form;
using detail::ScaledClosedForm;

Inverse2x2 inverse2x2(const Eigen::Matrix2d& A) {
  require_finite(A, "2x2 matrix");
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const ScaledClosedForm form = scaled_closed_form(A);
  const double determinant = form.exponent == 0 ? form.determinant : std::ldexp(form.determinant, 2 * form.exponent);

  // kappa + 1/kappa = ||A||_F^2 / |det A|  =>  kappa = (r + sqrt(r^2 - 4)) / 2 (infinity when det = 0).
  const double ratio = form.frobenius_squared / std::abs(form.determinant);
  const double kappa = std::isfinite(ratio) ? 0.5 * (ratio + std::sqrt(std::max(ratio * ratio - 4.0, 0.0))) : infinity;
  if (form.singular) return {Eigen::Matrix2d::Constant(nan), determinant, kappa, Status::singular};
  return {inverse_of(form), determinant, kappa, Status::converged};
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
