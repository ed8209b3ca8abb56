#include "numlab/linalg/inverse2x2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::linalg {

namespace detail {

ClosedForm scaled_by_power_of_two(const Eigen::Matrix2d& A) {
  ClosedForm form;
  const double largest = A.cwiseAbs().maxCoeff();
  if (largest > 0.0) std::frexp(largest, &form.exponent);  // largest = m 2^e, 1/2 <= m < 1 (subnormals too)
  // Entry by entry: exact (a power of two, the results in [1/2, 1) down to the underflow of tiny
  // entries), where A * 2^-e could not be, 2^-e being beyond the doubles for e < -1022.
  form.a = std::ldexp(A(0, 0), -form.exponent), form.b = std::ldexp(A(0, 1), -form.exponent);
  form.c = std::ldexp(A(1, 0), -form.exponent), form.d = std::ldexp(A(1, 1), -form.exponent);
  form.frobenius_squared = frobenius_squared(form.a, form.b, form.c, form.d);
  return form;
}

Eigen::Vector2d ClosedForm::solve_scaled(const Eigen::Vector2d& y) const {
  int y_exponent = 0;
  const double largest = y.cwiseAbs().maxCoeff();
  if (largest > 0.0) std::frexp(largest, &y_exponent);
  const double y0 = std::ldexp(y(0), -y_exponent), y1 = std::ldexp(y(1), -y_exponent);
  // |adjugate y| <= 2 and |det| > eps ||.||_F^2 >= eps / 4: the quotient is far inside the doubles.
  const double scale = 1.0 / determinant;
  return {std::ldexp(scale * (d * y0 - b * y1), y_exponent - exponent),
          std::ldexp(scale * (a * y1 - c * y0), y_exponent - exponent)};
}

}  // namespace detail

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// inverse2x2 for a matrix already known to be finite.
Inverse2x2 closed_form_inverse(const Eigen::Matrix2d& A) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const detail::ClosedForm form = detail::closed_form(A);
  const double determinant = form.exponent == 0 ? form.determinant : std::ldexp(form.determinant, 2 * form.exponent);

  // kappa + 1/kappa = ||A||_F^2 / |det A|  =>  kappa = (r + sqrt(r^2 - 4)) / 2 (infinity when det = 0).
  const double ratio = form.frobenius_squared / std::abs(form.determinant);
  const double kappa = std::isfinite(ratio) ? 0.5 * (ratio + std::sqrt(std::max(ratio * ratio - 4.0, 0.0))) : infinity;
  if (form.singular) return {Eigen::Matrix2d::Constant(nan), determinant, kappa, Status::singular};
  const Eigen::Matrix2d inverse = form.adjugate() * form.inverse_scale();
  return {inverse, determinant, kappa, inverse.allFinite() ? Status::converged : Status::non_finite};
}

}  // namespace

Inverse2x2 inverse2x2(const Eigen::Matrix2d& A) {
  require_finite(A, "2x2 matrix");
  return closed_form_inverse(A);
}

void ClosedForm2x2::start(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) {
  require_finite(b, "right-hand side");
  require_finite(A, "2x2 matrix");
  A_ = A;
  b_ = b;
  x_.setZero();
  residual_norm_ = LinearResult<2>::not_applicable;
  status_ = Status::running;
  running_ = true;
  iterations_ = 0;
}

bool ClosedForm2x2::step() {
  if (!running_) return false;
  // 1. A^-1 by the closed form.
  const Inverse2x2 closed_form = closed_form_inverse(A_);
  // 2. x = A^-1 b (NaN when singular). Where A^-1 overflows, x itself may still be a double: then
  //    x = adj(A) b / det, the scaling undone last.
  x_ = closed_form.inverse * b_;
  status_ = closed_form.status;
  if (status_ == Status::non_finite) {
    x_ = detail::closed_form(A_).solve(b_);
    status_ = Status::converged;
  }
  if (status_ == Status::converged) {
    if (!x_.allFinite()) {
      status_ = Status::non_finite;
    } else {
      residual_norm_ = residual_inf_norm(A_, b_, x_);
    }
  }
  iterations_ = 1;
  running_ = false;
  if (observer_ != nullptr) observer_->on_step(*this, {closed_form.determinant, closed_form.condition_number});
  return false;
}

LinearResult<2> ClosedForm2x2::result() const {
  LinearResult<2> result;
  result.x = x_;
  result.status = status_;
  result.iterations = iterations_;
  result.residual_norm = residual_norm_;
  return result;
}

LinearResult<2> solve2x2(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) { return ClosedForm2x2().solve(A, b); }

}  // namespace numlab::linalg
