#pragma once
// One dyad, the block of seed 000's sequential solve, as a system of two equations in two angles:
//
//   f(alpha, beta) = k + p u(alpha) - q u(beta) = 0,   u(t) = (sin t, cos t)  (sine row first),
//
//   J = [  p cos alpha   -q cos beta ]
//       [ -p sin alpha    q sin beta ]
//
// k = (k_y, k_x) is the known part: the crank and the links the blocks before this one have
// placed. nonlinear::Newton<DyadBlock, linalg::ClosedForm2x2> is the textbook sequential step:
// Newton's method with the closed-form 2x2 inverse, on one block. (DyadNewton, dyad_newton.hpp,
// is its specialised copy for the crank sweep.)

#include <Eigen/Core>
#include <cmath>

#include "numlab/nonlinear/system.hpp"

namespace numlab::mechanisms {

class DyadBlock : public nonlinear::EvaluatesTogether<DyadBlock, 2> {
 public:
  static constexpr int size = 2;

  DyadBlock(double known_y, double known_x, double p, double q) : known_y_(known_y), known_x_(known_x), p_(p), q_(q) {}

  // A new known part (the lengths stay).
  void set_known(double known_y, double known_x) {
    known_y_ = known_y;
    known_x_ = known_x;
  }

  int dimension() const { return size; }

  // x = (alpha, beta).
  void residual_and_jacobian(const Eigen::Vector2d& x, Eigen::Vector2d& f, Eigen::Matrix2d& J) const {
    const double cos_alpha = std::cos(x(0)), sin_alpha = std::sin(x(0));
    const double cos_beta = std::cos(x(1)), sin_beta = std::sin(x(1));
    f << known_y_ + p_ * sin_alpha - q_ * sin_beta,  // sine row
        known_x_ + p_ * cos_alpha - q_ * cos_beta;   // cosine row
    J << p_ * cos_alpha, -q_ * cos_beta,             //
        -p_ * sin_alpha, q_ * sin_beta;
  }

 private:
  double known_y_, known_x_, p_, q_;
};

}  // namespace numlab::mechanisms
