#pragma once
// Seed 001's ten closure equations f1 ... f10 (its eqs 8-17) as printed, in the unknowns
// x = (theta3 ... theta12) at a fixed crank angle theta2, with its analytic Jacobian (eq 20).
// With `copy_seed_slip`, rows 9-10 use 67.5 where |r12| = 65.7, as the seed's Jacobian does: lab
// material for the Jacobian check. (The Jansen models proper live in mechanisms/.)

#include <Eigen/Core>

#include "numlab/nonlinear/autodiff_system.hpp"

namespace numlab::cli {

class Seed001Closure final : public nonlinear::TemplatedResidual<Seed001Closure> {
 public:
  Seed001Closure(double crank_angle, bool copy_seed_slip) : crank_(crank_angle), slip_(copy_seed_slip) {}
  int dimension() const override { return 10; }

  template <typename T>
  void evaluate(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>& f) const {
    using std::cos;
    using std::sin;
    const double crank_x = 38.0 + 15.0 * std::cos(crank_), crank_y = 7.8 + 15.0 * std::sin(crank_);
    f(0) = crank_x + 50.0 * cos(x(0)) + 41.5 * cos(x(1));
    f(1) = crank_y + 50.0 * sin(x(0)) + 41.5 * sin(x(1));
    f(2) = -41.5 * cos(x(1)) + 55.8 * cos(x(2)) + 40.1 * cos(x(3));
    f(3) = -41.5 * sin(x(1)) + 55.8 * sin(x(2)) + 40.1 * sin(x(3));
    f(4) = 40.1 * cos(x(3)) - 39.4 * cos(x(4)) + 39.3 * cos(x(5)) - 36.7 * cos(x(6));
    f(5) = 40.1 * sin(x(3)) - 39.4 * sin(x(4)) + 39.3 * sin(x(5)) - 36.7 * sin(x(6));
    f(6) = crank_x - 39.3 * cos(x(5)) - 61.9 * cos(x(7));
    f(7) = crank_y - 39.3 * sin(x(5)) - 61.9 * sin(x(7));
    f(8) = 36.7 * cos(x(6)) + 49.0 * cos(x(8)) + 65.7 * cos(x(9));
    f(9) = 36.7 * sin(x(6)) + 49.0 * sin(x(8)) + 65.7 * sin(x(9));
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
