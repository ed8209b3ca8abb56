#pragma once
// A dynamic system whose residual can also be evaluated on Eigen's AutoDiff scalars, so that its
// hand-written Jacobian can be checked against an exact derivative (jacobian_check.hpp).

#include <unsupported/Eigen/AutoDiff>

#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

using AutoDiffScalar = Eigen::AutoDiffScalar<Eigen::VectorXd>;
using AutoDiffVector = Eigen::Matrix<AutoDiffScalar, Eigen::Dynamic, 1>;

class AutoDiffSystem : public DynamicSystem {
 public:
  virtual void residual_autodiff(const AutoDiffVector& x, AutoDiffVector& f) const = 0;
};

// Implements residual() and residual_autodiff() from one template, Derived::evaluate<Scalar>(x, f).
template <typename Derived>
class TemplatedResidual : public AutoDiffSystem {
 public:
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override {
    f.resize(dimension());
    static_cast<const Derived&>(*this).evaluate(x, f);
  }
  void residual_autodiff(const AutoDiffVector& x, AutoDiffVector& f) const override {
    f.resize(dimension());
    static_cast<const Derived&>(*this).evaluate(x, f);
  }
};

}  // namespace numlab::nonlinear
