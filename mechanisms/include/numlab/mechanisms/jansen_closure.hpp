#pragma once
// The Jansen leg's eight loop-closure equations, seed 000 eqs (1)-(8), in theta1 ... theta8 at a
// given crank angle theta_i (radians, counter-clockwise from +x). Frame and lengths: docs/mechanisms.md.
// O (crank pivot) is the origin, P1 = (-b, -a); each equation equates two paths to one joint:
//   (1,2)  B:  O -> A -> B            = P1 -> B                 (theta1, theta2)
//   (3,4)  C:  O -> A -> B -> C       = P1 -> C                 (theta1, theta3, theta4)
//   (5,6)  D:  O -> A -> D            = P1 -> D                 (theta6, theta7)
//   (7,8)  E:  O -> A -> B -> C -> E  = P1 -> D -> E            (theta1, theta3, theta5, theta7, theta8)
// Its Jacobian is block lower-triangular in the pairs (1,2), (3,4), (6,7), (5,8).
//
// residual_and_jacobian() computes each sine and cosine once for both, from the sine source
// (sine_sources.hpp): JansenClosure calls std::sin and std::cos; the crank sweep and the
// benchmark use JansenClosureOf<TableSines>, the same equations with a table's sines.

#include <Eigen/Core>

#include "numlab/linalg/linear_result.hpp"
#include "numlab/mechanisms/sine_sources.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::mechanisms {

struct JansenLengths {
  double crank = 15.0;  // li, O-A
  double l1 = 50.0, l2 = 41.5, l3 = 55.8, l4 = 40.1, l5 = 39.4, l6 = 61.9, l7 = 39.3, l8 = 36.7;
  double a = 7.8;   // P1 lies a below O
  double b = 38.0;  // and b to its left
};

// The foot triangle D-E-F's other two sides (l8 = D-E is the third), seed 000's l9 and l10.
struct JansenFootLengths {
  double l9 = 49.0;   // D-F
  double l10 = 65.7;  // E-F
};

template <typename Sines>
class JansenClosureOf : public nonlinear::EvaluatesTogether<JansenClosureOf<Sines>, 8> {
 public:
  static constexpr int size = 8;
  using Vector = linalg::Vector<8>;
  using Matrix = linalg::Matrix<8>;

  explicit JansenClosureOf(double crank_angle, JansenLengths lengths = {}) : lengths_(lengths) {
    set_crank_angle(crank_angle);
  }

  void set_crank_angle(double crank_angle);
  int dimension() const { return size; }
  void residual_and_jacobian(const Vector& theta, Vector& f, Matrix& J) const;

  // Seed 000 Table 3: theta1 ... theta8 at theta_i = 1.57 rad, the start of the seed's branch.
  static Vector seed_estimates();
  static constexpr double seed_crank_angle = 1.57;

 private:
  JansenLengths lengths_;
  double crank_x_ = 0.0, crank_y_ = 0.0;  // A - P1 = (li cos theta_i + b, li sin theta_i + a)
};

using JansenClosure = JansenClosureOf<LibrarySines>;  // the textbook closure

// Both instantiations are compiled once, in jansen_closure.cpp.
extern template class JansenClosureOf<LibrarySines>;
extern template class JansenClosureOf<TableSines>;

}  // namespace numlab::mechanisms
