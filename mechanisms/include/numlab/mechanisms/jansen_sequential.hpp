#pragma once
// Seed 000's sequential solve of the eight Jansen equations, the textbook way.
//
// The Jacobian is block lower-triangular in four pairs, so the closure is solved as four dyads
// in order (dyad_block.hpp), each by nonlinear::Newton<DyadBlock, linalg::ClosedForm2x2>:
//   block 0  (theta1, theta2):  k = A - P1                                    p = l1, q = l2
//   block 1  (theta3, theta4):  k = A - P1 + l1 u(theta1)                     p = l3, q = l4
//   block 2  (theta6, theta7):  k = A - P1                                    p = l6, q = l7
//   block 3  (theta5, theta8):  k = A - P1 + l1 u(theta1) + l3 u(theta3) - l7 u(theta7)
//                                                                             p = l5, q = l8
// with u(t) = (sin t, cos t) and A - P1 = (li sin theta_i + a, li cos theta_i + b) in (y, x) order.
// A block's known part uses the angles the blocks before it have just solved.
//
// The crank sweep's "sequential" solver (jansen_solvers.cpp) does the same with DyadNewton, the
// specialised copy of this Newton; tests/mechanisms/test_dyad_newton.cpp shows that both agree.

#include <Eigen/Core>
#include <array>

#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

// One block: its unknowns' indices in theta1 ... theta8 (0-based) and its lengths.
struct JansenDyad {
  int alpha, beta;
  double p, q;
};

// The four blocks, in solving order.
std::array<JansenDyad, 4> jansen_dyads(const JansenLengths& lengths = {});

// Block b's known part k = (k_y, k_x) at the crank angle, from the angles in theta that the blocks
// before b have solved (its own and later angles are not read). Sines from the library.
Eigen::Vector2d jansen_dyad_known(int b, double crank_angle, const Eigen::VectorXd& theta,
                                  const JansenLengths& lengths = {});

// The four Newtons in turn. Rejects nothing Newton accepts (damping included).
class TextbookSequentialJansen final : public JansenPoseSolver {
 public:
  explicit TextbookSequentialJansen(const nonlinear::NewtonOptions& options = {}) : options_(options) {}
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& theta) override;

 private:
  nonlinear::NewtonOptions options_;
};

}  // namespace numlab::mechanisms
