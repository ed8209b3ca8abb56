#pragma once
// Eigen's PartialPivLU, the second reference for the hand-written linear methods.
// This is the one place Eigen's decompositions are used as a solver.

#include <Eigen/LU>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/linear_result.hpp"

namespace numlab::linalg {

// Eigen::PartialPivLU. Eigen does not test for singularity: a zero pivot shows up as a non-finite
// solution, reported as Status::non_finite.
template <int N = Eigen::Dynamic>
class EigenLu {
 public:
  LinearResult<N> solve(const Matrix<N>& A, const Vector<N>& b) {
    require_valid_system(A, b);
    lu_.compute(A);
    LinearResult<N> result;
    result.iterations = 1;
    result.x = lu_.solve(b);
    result.status = result.x.allFinite() ? Status::converged : Status::non_finite;
    if (result.status == Status::converged) result.residual_norm = residual_inf_norm(A, b, result.x);
    return result;
  }

 private:
  Eigen::PartialPivLU<Matrix<N>> lu_;
};

}  // namespace numlab::linalg
