#pragma once
// Seed 001's 10-equation Jansen model: five loop closures f1 ... f10 (its eqs 8-17) in
// theta3 ... theta12 at crank angle theta2, the last loop being the rigid triangle D-E-F.
// The directions, read off its loop equations (seed 001's i, j, k, m, l, n are A, B, C, D, E, F):
//   theta3 A->B, theta4 B->P1, theta5 B->C, theta6 C->P1, theta7 C->E,
//   theta8 P1->D, theta9 E->D, theta10 D->A, theta11 D->F, theta12 F->E.
// It models the same leg as the 8-equation JansenClosure with two more unknowns and a closure
// equation pair for a triangle that is rigid anyway: over-modelling, kept to measure its cost.
// Its sines and cosines come from a sine source as the 8-equation model's do (sine_sources.hpp):
// Jansen10Closure calls the library, the sweep uses the table, so the two models' costs compare
// like with like.

#include <Eigen/Core>
#include <array>

#include "numlab/linalg/linear_result.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/sine_sources.hpp"

namespace numlab::mechanisms {

// f1 ... f10 for any scalar type (double, or AutoDiff for checking the Jacobian).
// crank_x, crank_y: the vector P1 -> A, i.e. (b + li cos theta2, a + li sin theta2).
template <typename Scalar>
void jansen10_residual(double crank_x, double crank_y, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x,
                       Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& f) {
  using std::cos;
  using std::sin;
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

template <typename Sines>
class Jansen10ClosureOf : public nonlinear::EvaluatesTogether<Jansen10ClosureOf<Sines>, 10> {
 public:
  static constexpr int size = 10;
  using Vector = linalg::Vector<10>;
  using Matrix = linalg::Matrix<10>;

  // The leg of seed 000's lengths by default; other lengths (an exercise variant's) give the same
  // ten equations with those lengths in place of the printed ones.
  explicit Jansen10ClosureOf(double crank_angle, JansenLengths lengths = {}, JansenFootLengths foot = {});
  void set_crank_angle(double crank_angle);
  int dimension() const { return size; }
  void residual_and_jacobian(const Vector& theta, Vector& f, Matrix& J) const;
  double crank_x() const { return crank_x_; }
  double crank_y() const { return crank_y_; }

 private:
  // Each closure term is length cos(x_column) in a cosine row and length sin(x_column) below it.
  struct Term {
    int row;  // the cosine row
    int column;
    double length;
  };
  JansenLengths lengths_;
  std::array<Term, 14> terms_;
  double crank_x_ = 0.0, crank_y_ = 0.0;
};

using Jansen10Closure = Jansen10ClosureOf<LibrarySines>;  // the textbook closure

// Both instantiations are compiled once, in jansen10_closure.cpp.
extern template class Jansen10ClosureOf<LibrarySines>;
extern template class Jansen10ClosureOf<TableSines>;

}  // namespace numlab::mechanisms
