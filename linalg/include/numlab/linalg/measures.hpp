#pragma once
// How good is a computed solution? The measures every lab table and the CLI report.

#include <Eigen/Core>

namespace numlab::linalg {

// ||b - A x||_inf / (||A||_inf ||x||_inf): the normwise relative residual (backward error).
// A backward-stable method keeps it near machine epsilon whatever kappa(A) is.
double relative_residual(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x);

// ||x - x_exact||_inf / ||x_exact||_inf. Expect up to about kappa(A) * relative_residual.
double forward_error(const Eigen::VectorXd& x, const Eigen::VectorXd& x_exact);

// An estimate of kappa_1(A) = ||A||_1 ||A^-1||_1 (Hager-Higham, from an LU factorization):
// usually within a small factor of the true value, never above it. Infinity for a singular A.
double condition_estimate(const Eigen::MatrixXd& A);

}  // namespace numlab::linalg
