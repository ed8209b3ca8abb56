#pragma once
// The Ford Mustang roof linkage of seed 003: eight loop-closure equations in the unknown angles
// A ... H at the input angle theta (radians). Frame, names and lengths: docs/mechanisms.md.
//
// Assumptions of this model (each also stated where it is used):
//  - Fixed points P0 = (sqrt 0.5, 0), P1 = (0, sqrt 0.5), P2 = (0, 1 + sqrt 0.5); theta is the
//    direction of link 2->4 from +x, counter-clockwise.
//  - A, B, D, F are directions from +x (counter-clockwise); C, E, G, H are measured from the
//    negative x-axis, turning towards +y: a link "at C" points along (-cos C, sin C) = u(pi - C).
//    (Seed 003 says so for C, G, H; its loop 3 equation treats E the same way, which its
//    conversion to degrees forgets.)
//  - Link lengths are seed 003's page-2 values. The 20-degree constants are exact (pi/9); the
//    seed's rounded 4.698 and 6.032 are replaced by the lengths they stand for.
//  - Major link 2-4-6-7 is rigid: |2 4| = |4 6| = 2.5 with 4->6 turned 40 degrees from 2->4, so
//    the chord 2->6 is 2 (2.5) cos 20 long at theta + 20 (the seed's 4.698 at theta + pi/9),
//    and 7 continues that chord by |6 7| = 4/3 (the seed's 6.032 = 4.698 + 4/3).
//  - Major link 5-6-8-9 is rigid: 5->6 at u(pi - C), 6->8 (length 4) at u(pi - C + 20 deg),
//    8->9 (length 1) at u(pi - C - 20 deg), as in the seed's point 8, point 9 and loops 3-4.
//
// Unknowns x = (A, B, C, D, E, F, G, H); loop k closes in the pair (x(2k), x(2k+1)):
//   loop 1 (A, B): quadrilateral 1-2-4-3, P4 reached from P1 through P3       (theta)
//   loop 2 (C, D): quadrilateral 0-2-6-5, P6 reached from P0 through P5       (theta)
//   loop 3 (E, F): quadrilateral 6-7-10-8, P10 from P7 and from P8           (theta, C)
//   loop 4 (G, H): quadrilateral 8-10-11-9, P11 from P10 and from P9         (C, F)
// Each loop k is  f_k = known_k + (a_x cos alpha, a_y sin alpha) + (b_x cos beta, b_y sin beta),
// where known_k holds theta and the unknowns solved before it: the Jacobian is block
// lower-triangular in the four 2x2 pairs (seed 003's order), so sequential and full Newton have
// the same roots.

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "numlab/linalg/linear_result.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::mechanisms {

// Seed 003, page 2 (joint a -> joint b as l_a_b), and the 20-degree bend.
struct MustangLengths {
  double l0_1 = 1.0, l1_2 = 1.0, l1_3 = 2.0, l3_4 = 2.0, l0_5 = 5.0, l2_4 = 2.5, l4_6 = 2.5;
  double l6_7 = 4.0 / 3.0, l5_6 = 4.0 / 3.0, l6_8 = 4.0, l8_9 = 1.0, l7_10 = 4.5, l10_8 = 4.0 / 3.0;
  double l10_11 = 4.0 / 3.0, l9_11 = 1.0, l11_12 = 4.0 / 3.0;
  double bend = std::numbers::pi / 9.0;  // 20 degrees
  // |2 6|: the chord of the isosceles bend 2-4-6 (|2 4| = |4 6|), the seed's 4.698.
  double chord2_6() const { return 2.0 * l2_4 * std::cos(bend); }
};

// One loop: f = known + (a_x cos alpha, a_y sin alpha) + (b_x cos beta, b_y sin beta).
struct LoopTerms {
  Eigen::Vector2d known, a, b;
};

class MustangClosure : public nonlinear::EvaluatesTogether<MustangClosure, 8> {
 public:
  static constexpr int size = 8;
  static constexpr int loops = 4;
  using Vector = linalg::Vector<8>;
  using Matrix = linalg::Matrix<8>;

  explicit MustangClosure(double theta, MustangLengths lengths = {}) : lengths_(lengths) { set_crank_angle(theta); }

  void set_crank_angle(double theta);
  double crank_angle() const { return theta_; }
  int dimension() const { return size; }
  void residual_and_jacobian(const Vector& x, Vector& f, Matrix& J) const;

  // Loop k (0 ... 3) with the unknowns before it taken from x (its own pair is not read).
  LoopTerms loop(int k, const Vector& x) const;

  const MustangLengths& lengths() const { return lengths_; }

  // Seed 003's start: every pair from [pi/18, pi/2], at theta = 45 degrees.
  static Vector seed_guess();
  static constexpr double seed_crank_deg = 45.0;

 private:
  MustangLengths lengths_;
  double theta_ = 0.0;
  Eigen::Vector2d input_, bent_;  // u(theta), u(theta + bend)
};

// One loop as a 2x2 system in its own pair (alpha, beta), the loops before it held fixed in
// `terms`: what sequential Newton solves, four times in order.
struct MustangLoop : nonlinear::EvaluatesTogether<MustangLoop, 2> {
  static constexpr int size = 2;
  LoopTerms terms;
  int dimension() const { return 2; }
  void residual_and_jacobian(const Eigen::Vector2d& v, Eigen::Vector2d& f, Eigen::Matrix2d& J) const {
    const double ca = std::cos(v(0)), sa = std::sin(v(0)), cb = std::cos(v(1)), sb = std::sin(v(1));
    f << terms.known.x() + terms.a.x() * ca + terms.b.x() * cb, terms.known.y() + terms.a.y() * sa + terms.b.y() * sb;
    J << -terms.a.x() * sa, -terms.b.x() * sb, terms.a.y() * ca, terms.b.y() * cb;
  }
};

}  // namespace numlab::mechanisms
