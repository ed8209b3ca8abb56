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

#include "numlab/linalg/linear_result.hpp"

namespace numlab::linalg {

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
  LinearResult<2> solve_prechecked(const Eigen::Matrix2d& A, const Eigen::Vector2d& b) const;
};

}  // namespace numlab::linalg
