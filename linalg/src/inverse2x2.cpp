#include "numlab/linalg/inverse2x2.hpp"

#include <cmath>
#include <limits>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::linalg {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// What every use of the closed form needs: A scaled by a power of two, its determinant and the
// singular test. The scaling keeps a d and b c from overflowing or underflowing; it is exact,
// and when max|a_ij| lies within 2^-200 ... 2^200 neither can happen (an underflowed product
// would be below 2^-600 of any determinant that passes the test), so it is skipped there.
struct ScaledClosedForm {
  Eigen::Matrix2d scaled = Eigen::Matrix2d::Zero();  // A / 2^exponent
  int exponent = 0;
  double determinant = 0.0;   // det of the scaled matrix
  double frobenius_squared = 0.0;
  bool singular = true;       // |det| <= eps ||A||_F^2 (kappa_2 >= 1/eps), or A = 0
};

ScaledClosedForm scaled_closed_form(const Eigen::Matrix2d& A) {
  ScaledClosedForm form;
  const double largest = A.cwiseAbs().maxCoeff();
  if (largest == 0.0) return form;
  if (largest < 0x1p-200 || largest > 0x1p200) std::frexp(largest, &form.exponent);
  form.scaled = form.exponent == 0 ? A : Eigen::Matrix2d(A * std::ldexp(1.0, -form.exponent));
  const double a = form.scaled(0, 0), b = form.scaled(0, 1), c = form.scaled(1, 0), d = form.scaled(1, 1);
  form.determinant = a * d - b * c;
  form.frobenius_squared = form.scaled.squaredNorm();
  form.singular = std::abs(form.determinant) <= std::numeric_limits<double>::epsilon() * form.frobenius_squared;
  return form;
}

// A^-1 = (1/det) [d -b; -c a], with the scaling undone.
Eigen::Matrix2d inverse_of(const ScaledClosedForm& form) {
  Eigen::Matrix2d inverse;
  inverse << form.scaled(1, 1), -form.scaled(0, 1), -form.scaled(1, 0), form.scaled(0, 0);
  const double inverse_determinant = 1.0 / form.determinant;
  return inverse * (form.exponent == 0 ? inverse_determinant : std::ldexp(inverse_determinant, -form.exponent));
}

}  // namespace

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

LinearResult<2> ClosedForm2x2::solve_prechecked(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) const {
  const ScaledClosedForm form = scaled_closed_form(A);
  LinearResult<2> result;
  result.iterations = 1;
  if (form.singular) {
    result.status = Status::singular;
    result.x.setConstant(nan);
  } else {
    result.x = inverse_of(form) * b;
    if (!result.x.allFinite()) result.status = Status::non_finite;
  }
  return result;
}

}  // namespace numlab::linalg
