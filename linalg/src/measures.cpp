#include "numlab/linalg/measures.hpp"

#include <cmath>

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
  // kappa does not change with scale, so A is first scaled by a power of two (exactly) to have its
  // largest entry in [1, 2): a matrix of tiny (even subnormal) or huge entries does not over- or
  // underflow in the estimate. Eigen's rcond() is the LAPACK-style Hager-Higham estimate of 1 / kappa_1.
  const double largest = A.size() == 0 ? 0.0 : A.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return std::numeric_limits<double>::infinity();
  const int exponent = -std::ilogb(largest);  // up to 1074 for a subnormal: 2^1074 overflows, so in two halves
  const Eigen::MatrixXd scaled = (A * std::ldexp(1.0, exponent / 2)) * std::ldexp(1.0, exponent - exponent / 2);
  const double reciprocal = Eigen::PartialPivLU<Eigen::MatrixXd>(scaled).rcond();
  if (!(reciprocal > 0.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / reciprocal;
}

}  // namespace numlab::linalg
