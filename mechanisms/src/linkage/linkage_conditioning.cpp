#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

#include <Eigen/SVD>
#include <limits>

namespace numlab::mechanisms {

LinkageConditioning linkage_conditioning(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  Eigen::MatrixXd J;
  model.jacobian(q, t, J);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
  const auto& s = svd.singularValues();
  if (s.size() == 0) return {1.0, 0.0};
  const double smallest = s(s.size() - 1);
  if (smallest == 0.0) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return {s(0) / smallest, 1.0 / smallest};
}

}  // namespace numlab::mechanisms
