#pragma once
// The Result every linear method returns, direct or iterative.

#include <Eigen/Core>
#include <limits>

#include "numlab/status.hpp"

namespace numlab::linalg {

template <int N>
using Vector = Eigen::Matrix<double, N, 1>;

template <int N>
using Matrix = Eigen::Matrix<double, N, N>;

// A defined starting value for a stepper's Eigen member: zero for fixed sizes (so copying or
// moving a stepper never reads uninitialized memory), empty for dynamic ones (sized in start()).
template <typename EigenType>
EigenType zero_or_empty() {
  if constexpr (EigenType::SizeAtCompileTime == Eigen::Dynamic) {
    return EigenType();
  } else {
    return EigenType::Zero();
  }
}

template <int N>
struct LinearResult {
  static constexpr double not_applicable = std::numeric_limits<double>::quiet_NaN();

  Vector<N> x = Vector<N>::Zero(N == Eigen::Dynamic ? 0 : N);  // the computed solution
  Status status = Status::running;        // until the method sets its verdict (numlab/status.hpp)
  int iterations = 0;                     // pivot columns (GEPP), sweeps (Gauss-Seidel), 1 (closed form)
  double residual_norm = not_applicable;  // ||b - A x||_inf of the original system
  double step_norm = not_applicable;      // last ||x_k - x_{k-1}||_inf (iterative methods)
  double growth_factor = not_applicable;  // max|U| / max|A| (Gaussian elimination)
};

// ||b - A x||_inf, the absolute residual of the original system. Small fixed sizes use a
// coefficient-wise product that unrolls; others use Eigen's blocked matrix-vector kernel.
template <typename MatrixType, typename VectorType, typename SolutionType>
double residual_inf_norm(const MatrixType& A, const VectorType& b, const SolutionType& x) {
  if constexpr (MatrixType::RowsAtCompileTime != Eigen::Dynamic && MatrixType::RowsAtCompileTime <= 16) {
    return (b - A.lazyProduct(x)).template lpNorm<Eigen::Infinity>();
  } else {
    return (b - A * x).template lpNorm<Eigen::Infinity>();
  }
}

}  // namespace numlab::linalg
