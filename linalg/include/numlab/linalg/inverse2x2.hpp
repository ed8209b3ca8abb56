#pragma once
// The 2x2 closed form (seed 003's inner solve):
//
//   A = [a b; c d],   det A = a d - b c,   A^-1 = (1 / det A) [d -b; -c a],   x = A^-1 y.
//
// The determinant is judged relative to the matrix's scale: for a 2x2 matrix
//   ||A||_F^2 / |det A| = sigma_1/sigma_2 + sigma_2/sigma_1 = kappa_2 + 1/kappa_2,
// so |det A| <= eps * ||A||_F^2 means kappa_2(A) >= 1/eps: the matrix is singular to working
// precision and the result is Status::singular. The same ratio gives kappa_2 exactly.
// A is first scaled by a power of two (exact) so that a d and b c cannot overflow or underflow,
// when its entries are large or small enough for that to be possible.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::linalg {

namespace detail {

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

inline ScaledClosedForm scaled_closed_form(const Eigen::Matrix2d& A) {
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
inline Eigen::Matrix2d inverse_of(const ScaledClosedForm& form) {
  Eigen::Matrix2d inverse;
  inverse << form.scaled(1, 1), -form.scaled(0, 1), -form.scaled(1, 0), form.scaled(0, 0);
  const double inverse_determinant = 1.0 / form.determinant;
  return inverse * (form.exponent == 0 ? inverse_determinant : std::ldexp(inverse_determinant, -form.exponent));
}

}  // namespace detail

struct Inverse2x2 {
  Eigen::Matrix2d inverse;  // NaN when singular
  double determinant;       // det A
  double condition_number;  // kappa_2(A), exact; infinity when det A = 0
  Status status;            // converged or singular
};

// Throws std::invalid_argument when A has a non-finite entry.
Inverse2x2 inverse2x2(const Eigen::Matrix2d& A);

// x = A^-1 b by the closed form. Throws std::invalid_argument on non-finite input.
LinearResult<2> solve2x2(const Eigen::Matrix2d& A, const Eigen::Vector2d& b);

// The closed form with the solver interface shared by every linear method.
class ClosedForm2x2 {
 public:
  LinearResult<2> solve(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) const { return solve2x2(A, b); }
  // For a caller that has already checked A and b are finite (Newton's inner solve): the same
  // x and singular test, without the input screens, kappa or the residual (not applicable).
  LinearResult<2> solve_prechecked(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) const {
    LinearResult<2> result;
    result.iterations = 1;
    const double a11 = A(0, 0), a12 = A(0, 1), a21 = A(1, 0), a22 = A(1, 1);
    const double frobenius_squared = a11 * a11 + a12 * a12 + a21 * a21 + a22 * a22;
    // 2^-398 <= ||A||_F^2 <= 2^400 puts max|a_ij| within 2^-200 ... 2^200 (||A||_F^2 <= 4 max^2).
    if (frobenius_squared >= 0x1p-398 && frobenius_squared <= 0x1p400) {
      // The usual case: no scaling needed (see detail::scaled_closed_form), so the formulas directly.
      const double determinant = a11 * a22 - a12 * a21;
      if (std::abs(determinant) <= std::numeric_limits<double>::epsilon() * frobenius_squared) {
        result.status = Status::singular;
        result.x.setConstant(std::numeric_limits<double>::quiet_NaN());
        return result;
      }
      const double inverse_determinant = 1.0 / determinant;
      result.x << inverse_determinant * (a22 * b(0) - a12 * b(1)), inverse_determinant * (a11 * b(1) - a21 * b(0));
    } else {
      const detail::ScaledClosedForm form = detail::scaled_closed_form(A);
      if (form.singular) {
        result.status = Status::singular;
        result.x.setConstant(std::numeric_limits<double>::quiet_NaN());
        return result;
      }
      result.x = detail::inverse_of(form) * b;
    }
    if (!std::isfinite(result.x(0)) || !std::isfinite(result.x(1))) result.status = Status::non_finite;
    return result;
  }
};

}  // namespace numlab::linalg
