#pragma once
// Seed 001's ten closure equations f1 ... f10 (its eqs 8-17; mechanisms::jansen10_residual), in the
// unknowns x = (theta3 ... theta12) at a fixed crank angle theta2, with its analytic Jacobian (eq 20).
// With `copy_seed_slip`, rows 9-10 use 67.5 where |r12| = 65.7, as the seed's Jacobian does: lab
// material for the Jacobian check. (The Jansen models proper live in mechanisms/.)

#include <Eigen/Core>

#include <cmath>

#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/nonlinear/autodiff_system.hpp"

namespace numlab::cli {

class Seed001Closure final : public nonlinear::TemplatedResidual<Seed001Closure> {
 public:
  Seed001Closure(double crank_angle, bool copy_seed_slip) : crank_(crank_angle), slip_(copy_seed_slip) {}
  int dimension() const override { return 10; }

  template <typename T>
  void evaluate(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>& f) const {
    mechanisms::jansen10_residual(38.0 + 15.0 * std::cos(crank_), 7.8 + 15.0 * std::sin(crank_), x, f);
  }

  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override;

  // Seed 001's Table 2 estimates of theta3 ... theta12, and its crank angle theta2 = 0.576.
  static Eigen::VectorXd seed_estimates();
  static constexpr double seed_crank_angle = 0.576;

 private:
  double crank_;
  bool slip_;
};

}  // namespace numlab::cli
