#include "numlab/mechanisms/jansen_sequential.hpp"

#include <algorithm>
#include <cmath>

#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/dyad_block.hpp"

namespace numlab::mechanisms {

namespace {
Eigen::Vector2d u(double angle) { return {std::sin(angle), std::cos(angle)}; }  // (y, x) order
}  // namespace

std::array<JansenDyad, 4> jansen_dyads(const JansenLengths& L) {
  return {{{0, 1, L.l1, L.l2}, {2, 3, L.l3, L.l4}, {5, 6, L.l6, L.l7}, {4, 7, L.l5, L.l8}}};
}

Eigen::Vector2d jansen_dyad_known(int b, double crank_angle, const Eigen::VectorXd& theta, const JansenLengths& L) {
  const Eigen::Vector2d crank(L.a + L.crank * std::sin(crank_angle), L.b + L.crank * std::cos(crank_angle));
  switch (b) {
    case 1: return crank + L.l1 * u(theta(0));
    case 3: return crank + L.l1 * u(theta(0)) + L.l3 * u(theta(2)) - L.l7 * u(theta(6));
    default: return crank;  // blocks 0 and 2
  }
}

PoseOutcome TextbookSequentialJansen::solve(double crank_angle, Eigen::VectorXd& theta) {
  PoseOutcome total;
  const std::array<JansenDyad, 4> dyads = jansen_dyads();
  for (int b = 0; b < 4; ++b) {
    const JansenDyad& dyad = dyads[static_cast<std::size_t>(b)];
    // 1. The block, with its known part from the crank and the blocks already solved.
    const Eigen::Vector2d known = jansen_dyad_known(b, crank_angle, theta);
    const DyadBlock block(known(0), known(1), dyad.p, dyad.q);
    // 2. Newton with the closed-form 2x2 inverse, from the block's angles in theta.
    const auto result = nonlinear::newton_solve(block, Eigen::Vector2d(theta(dyad.alpha), theta(dyad.beta)), options_,
                                                linalg::ClosedForm2x2());
    // 3. Its angles into theta, where the blocks after it read them.
    theta(dyad.alpha) = result.x(0);
    theta(dyad.beta) = result.x(1);
    total.iterations += result.iterations;
    // Block lower-triangular: the largest block residual is the whole system's ||f||_inf.
    total.residual_norm = std::max(total.residual_norm, result.residual_norm);
    if (result.status != Status::converged) {
      total.status = result.status;  // the blocks after it are not tried
      return total;
    }
  }
  total.status = Status::converged;
  return total;
}

}  // namespace numlab::mechanisms
