#pragma once
// Tolerances for comparing two solutions of A x = b, derived from the problem's conditioning:
// a backward-stable solve has relative error up to about n * kappa(A) * eps (times the growth
// factor for elimination), so two such solutions agree to that, with a safety factor.

#include <Eigen/Core>
#include <limits>

#include "numlab/linalg/measures.hpp"

namespace numlab::test {

constexpr double eps = std::numeric_limits<double>::epsilon();

inline double agreement_tolerance(const Eigen::MatrixXd& A, double growth = 1.0) {
  return 10.0 * static_cast<double>(A.rows()) * growth * linalg::condition_estimate(A) * eps;
}

// ||x - y||_inf / ||y||_inf
template <typename X, typename Y>
double relative_difference(const Eigen::MatrixBase<X>& x, const Eigen::MatrixBase<Y>& y) {
  return (x - y).template lpNorm<Eigen::Infinity>() / y.template lpNorm<Eigen::Infinity>();
}

}  // namespace numlab::test
