#pragma once
// Is a hand-derived Jacobian right? Compare it, entry by entry, with
//   - central finite differences: (f(x + h e_j) - f(x - h e_j)) / 2h, h = cbrt(eps) max(1, |x_j|),
//     accurate to about 1e-10 relative for smooth f (truncation h^2 against rounding eps/h);
//   - Eigen's AutoDiff (unsupported/Eigen/AutoDiff), exact to rounding, when the system can
//     evaluate its residual on AutoDiff scalars (AutoDiffSystem).
// and name the worst entry. Seed 001's printed Jacobian has 67.5 where |r12| = 65.7: this finds it.

#include <Eigen/Core>
#include <string>

#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

struct JacobianCheck {
  Eigen::MatrixXd analytic;
  Eigen::MatrixXd finite_difference;
  Eigen::MatrixXd autodiff;  // empty when the system does not support AutoDiff
  // |analytic - reference| / max(1, |reference|), the reference being AutoDiff when present.
  double worst_error = 0.0;
  int worst_row = 0, worst_column = 0;  // 0-based
  double finite_difference_agreement = 0.0;  // the same measure between FD and AutoDiff (how good FD is)
  double tolerance = 0.0;
  bool agrees = true;  // worst_error <= tolerance
};

// tolerance: the largest acceptable relative error; 1e-6 flags any real slip while leaving
// room for finite differences' own error.
JacobianCheck check_jacobian(const DynamicSystem& system, const Eigen::VectorXd& x, double tolerance = 1e-6);

// "J(9,9) = -49.2 but the reference says -47.9 (relative error 0.027)": one line for the worst entry.
std::string describe_worst_entry(const JacobianCheck& check);

}  // namespace numlab::nonlinear
