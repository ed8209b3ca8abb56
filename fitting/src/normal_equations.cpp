#include "numlab/fitting/normal_equations.hpp"

#include <vector>

namespace numlab::fitting {

NormalEquations build_normal_equations(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  const int size = degree + 1;
  // 1. The power sums S_k = sum_i x_i^k for k = 0 .. 2D, and the moments T_k = sum_i x_i^k y_i.
  std::vector<double> power_sums(static_cast<std::size_t>(2 * degree + 1), 0.0);
  Eigen::VectorXd moments = Eigen::VectorXd::Zero(size);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    double power = 1.0;  // x_i^k
    for (int k = 0; k <= 2 * degree; ++k) {
      power_sums[static_cast<std::size_t>(k)] += power;
      if (k <= degree) moments(k) += power * y(i);
      power *= x(i);
    }
  }
  // 2. Entry (j, k) of V^T V is S_{j+k}: the matrix is a Hankel matrix of the power sums.
  Eigen::MatrixXd matrix(size, size);
  for (int j = 0; j < size; ++j) {
    for (int k = 0; k < size; ++k) matrix(j, k) = power_sums[static_cast<std::size_t>(j + k)];
  }
  return {matrix, moments};
}

}  // namespace numlab::fitting
