#include "numlab/linalg/measures.hpp"

#include <Eigen/LU>
#include <limits>

namespace numlab::linalg {

namespace {
double matrix_inf_norm(const Eigen::MatrixXd& A) { return A.cwiseAbs().rowwise().sum().maxCoeff(); }
}  // namespace

double relative_residual(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  const double residual = (b - A * x).lpNorm<Eigen::Infinity>();
  const double scale = matrix_inf_norm(A) * x.lpNorm<Eigen::Infinity>();
  if (scale == 0.0) return residual == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return residual / scale;
}

double forward_error(const Eigen::VectorXd& x, const Eigen::VectorXd& x_exact) {
  const double size = x_exact.lpNorm<Eigen::Infinity>();
  const double error = (x - x_exact).lpNorm<Eigen::Infinity>();
  if (size == 0.0) return error;
  return error / size;
}

double condition_estimate(const Eigen::MatrixXd& A) {
  // Eigen's rcond() is the LAPACK-style Hager-Higham estimate of 1 / kappa_1.
  const double reciprocal = Eigen::PartialPivLU<Eigen::MatrixXd>(A).rcond();
  if (!(reciprocal > 0.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / reciprocal;
}

}  // namespace numlab::linalg
