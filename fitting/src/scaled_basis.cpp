#include "numlab/fitting/scaled_basis.hpp"

namespace numlab::fitting {

AffineScaling scaling_for(const Eigen::VectorXd& x) {
  const double low = x.minCoeff();
  const double high = x.maxCoeff();
  const double half_width = 0.5 * (high - low);
  return {0.5 * (low + high), half_width > 0.0 ? half_width : 1.0};
}

Eigen::VectorXd to_scaled(const Eigen::VectorXd& x, const AffineScaling& scaling) {
  return (x.array() - scaling.centre) / scaling.scale;
}

}  // namespace numlab::fitting
