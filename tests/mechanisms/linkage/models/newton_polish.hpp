#pragma once
// A pose of a linkage model polished to rounding for the tests: `steps` full Newton steps from q at
// driver value t (model units), J solved by LU with partial pivoting. A solver's pose so polished
// is a reference for central differences and for virtual work.

#include <Eigen/LU>

#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::mechanisms::testing {

inline Eigen::VectorXd polish(const LinkageModel& model, double t, Eigen::VectorXd q, int steps = 8) {
  Eigen::VectorXd f;
  Eigen::MatrixXd J;
  for (int k = 0; k < steps; ++k) {
    model.residual(q, t, f);
    model.jacobian(q, t, J);
    q -= J.partialPivLu().solve(f);
  }
  return q;
}

}  // namespace numlab::mechanisms::testing
