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
// when its entries are large or small enough for that to be possible: 2^e just above max|a_ij|,
// e from the largest entry's binary exponent (subnormal entries included), each entry scaled by
// std::ldexp (so 2^-e itself never has to be a double: for 1e-320 I it would be 2^1063).
// A solve x = A^-1 b undoes the scaling after dividing by det, with b scaled by its own power of
// two: x can be a double where A^-1 is not (A = 1e-320 I, b = 1e-320 (1, 1): x = (1, 1)).
//
// The formula is written once, in detail::closed_form(); inverse2x2(), solve2x2(), the stepper
// ClosedForm2x2 and Newton's inner solve ClosedForm2x2::solve_prechecked() all use it.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "numlab/linalg/linear_result.hpp"
#include "numlab/solver.hpp"

namespace numlab::linalg {

namespace detail {

// max|a_ij|^2 <= ||A||_F^2 <= 4 max|a_ij|^2, so this range keeps max|a_ij| within 2^-200 ... 2^200:
// there a d and b c cannot overflow, and a product that underflows is below 2^-600 of any
// determinant that passes the singular test. Outside it, A is scaled by a power of two first.
constexpr bool needs_no_scaling(double frobenius_squared) {
  return frobenius_squared >= 0x1p-398 && frobenius_squared <= 0x1p400;
}

// The closed form of A / 2^exponent = [a b; c d] (exponent 0 unless A needs scaling).
struct ClosedForm {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
  int exponent = 0;
  double frobenius_squared = 0.0;  // a^2 + b^2 + c^2 + d^2
  double determinant = 0.0;        // a d - b c
  bool singular = true;            // |det| <= eps ||.||_F^2, that is kappa_2 >= 1/eps (or A = 0)

  // A^-1 = inverse_scale() * adjugate(): 1/det, with the scaling undone.
  double inverse_scale() const { return exponent == 0 ? 1.0 / determinant : std::ldexp(1.0 / determinant, -exponent); }
  Eigen::Matrix2d adjugate() const { return (Eigen::Matrix2d() << d, -b, -c, a).finished(); }

  // x = A^-1 y = adjugate() y / det, for a form that is not singular.
  Eigen::Vector2d solve(const Eigen::Vector2d& y) const {
    if (exponent == 0) {
      const double scale = 1.0 / determinant;
      return {scale * (d * y(0) - b * y(1)), scale * (a * y(1) - c * y(0))};
    }
    return solve_scaled(y);
  }

  // The same with the scaling undone last: 2^(f - e) adjugate() (y / 2^f) / det, 2^f just above max|y_i|.
  Eigen::Vector2d solve_scaled(const Eigen::Vector2d& y) const;
};

inline double frobenius_squared(double a, double b, double c, double d) { return (a * a + b * b) + (c * c + d * d); }

// A scaled by 2^-exponent, with 2^exponent just above max|a_ij| (the rare case: out of line).
ClosedForm scaled_by_power_of_two(const Eigen::Matrix2d& A);

// det = a d - b c and the singular test |det| <= eps ||A||_F^2, on A scaled when it must be.
inline ClosedForm closed_form(const Eigen::Matrix2d& A) {
  ClosedForm form;
  form.a = A(0, 0), form.b = A(0, 1), form.c = A(1, 0), form.d = A(1, 1);
  form.frobenius_squared = frobenius_squared(form.a, form.b, form.c, form.d);
  if (!needs_no_scaling(form.frobenius_squared)) form = scaled_by_power_of_two(A);
  form.determinant = form.a * form.d - form.b * form.c;
  form.singular = std::abs(form.determinant) <= std::numeric_limits<double>::epsilon() * form.frobenius_squared;
  return form;
}

}  // namespace detail

struct Inverse2x2 {
  Eigen::Matrix2d inverse;  // NaN when singular; not finite when A^-1 overflows (status non_finite)
  double determinant;       // det A
  double condition_number;  // kappa_2(A), exact; infinity when det A = 0
  Status status;            // converged, singular, or non_finite (A^-1 is beyond the doubles)
};

// Throws std::invalid_argument when A has a non-finite entry.
Inverse2x2 inverse2x2(const Eigen::Matrix2d& A);

// x = A^-1 b by the closed form. Throws std::invalid_argument on non-finite input.
LinearResult<2> solve2x2(const Eigen::Matrix2d& A, const Eigen::Vector2d& b);

// What the closed form's one step found: sent to an observer, if one is attached.
struct ClosedFormRecord {
  double determinant;       // det A
  double condition_number;  // kappa_2(A)
};

// The closed form as a stepper (numlab/solver.hpp) with the interface every linear method shares.
// Its one step is the whole solve: x = A^-1 b, as solve2x2.
class ClosedForm2x2 {
 public:
  using Observer = StepObserver<ClosedForm2x2, ClosedFormRecord>;

  void set_observer(Observer* observer) { observer_ = observer; }

  // Loads A x = b; throws std::invalid_argument on non-finite input.
  void start(const Eigen::Matrix2d& A, const Eigen::Vector2d& b);
  // The one step: A^-1 by the closed form, then x = A^-1 b (when A^-1 overflows, x = adj(A) b / det
  // with the scaling undone last). Returns false: the solve is over.
  bool step();
  LinearResult<2> solve(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) {
    start(A, b);
    step();
    return result();
  }
  LinearResult<2> result() const;

  bool running() const { return running_; }
  Status status() const { return status_; }
  // Never: the one step ends the run before the observer sees it, so there is nothing left to stop.
  bool stopped() const { return false; }
  int iterations() const { return iterations_; }  // 0 until the step, then 1
  const Eigen::Vector2d& x() const { return x_; }
  const Eigen::Matrix2d& matrix() const { return A_; }  // A, as start() loaded it
  const Eigen::Vector2d& rhs() const { return b_; }     // b

  // For a caller that has already checked A and b are finite (Newton's inner solve): the same
  // closed form and singular test, without the input screens, kappa or the residual (not
  // computed), as x = (1/det) ([d -b; -c a] b).
  LinearResult<2> solve_prechecked(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) const {
    LinearResult<2> result;
    result.iterations = 1;
    const detail::ClosedForm form = detail::closed_form(A);
    if (form.singular) {
      result.status = Status::singular;
      result.x.setConstant(std::numeric_limits<double>::quiet_NaN());
      return result;
    }
    result.x = form.solve(b);
    result.status = std::isfinite(result.x(0)) && std::isfinite(result.x(1)) ? Status::converged : Status::non_finite;
    return result;
  }

 private:
  Observer* observer_ = nullptr;
  Eigen::Matrix2d A_ = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d x_ = Eigen::Vector2d::Zero();
  double residual_norm_ = LinearResult<2>::not_applicable;
  Status status_ = Status::running;
  bool running_ = false;
  int iterations_ = 0;
};

}  // namespace numlab::linalg
