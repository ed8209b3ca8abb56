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
  if (largest > 0.0) std::frexp(largest, &form.exponent);
  const Eigen::Matrix2d scaled = A * std::ldexp(1.0, -form.exponent);  // exact: a power of two
  form.a = scaled(0, 0), form.b = scaled(0, 1), form.c = scaled(1, 0), form.d = scaled(1, 1);
  form.frobenius_squared = frobenius_squared(form.a, form.b, form.c, form.d);
  return form;
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
  return {form.adjugate() * form.inverse_scale(), determinant, kappa, Status::converged};
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
  const Inverse2x2 closed_form = closed_form_inverse(A_);
  x_ = closed_form.inverse * b_;  // NaN when singular
  status_ = closed_form.status;
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
