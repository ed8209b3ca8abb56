#pragma once
// The systems `numlab basins` maps, each with its assembly modes and a classifier that names the
// mode of a converged root only after checking it against the closed form of that mode:
//   CubeRoots  z^3 - 1 = 0 as two real equations (x, y); modes: the roots e^{2 pi i k / 3}, k = 0, 1, 2;
//   FourBar    a Grashof four-bar at a fixed crank angle, unknowns the coupler and rocker angles;
//              modes: the side of the line A -> O4 on which the coupler-rocker joint B lies;
//   the Jansen leg (JansenModes): the 8-angle closure; modes: the sides of its four dyads.
// A root that matches no mode's closed form gets nonlinear::unknown_mode, never a neighbour's label.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/nonlinear/basin_map.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::basins {

using nonlinear::Matrix;
using nonlinear::Vector;

// Distance within which a converged root is taken to be a mode's closed-form root: a thousand
// times the residual tolerance (1e-9), room for a Jacobian whose inverse magnifies f by 1e3.
inline constexpr double closed_form_match = 1e-6;

// z^3 - 1 with z = x + i y: f = (x^3 - 3 x y^2 - 1, 3 x^2 y - y^3); J = [[a, -b], [b, a]] with
// a = 3 (x^2 - y^2), b = 6 x y (the Cauchy-Riemann form of f'(z) = 3 z^2).
struct CubeRoots {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Vector<2>& z, Vector<2>& f) const;
  void jacobian(const Vector<2>& z, Matrix<2>& J) const;
  static Eigen::Vector2d root(int k);  // (cos 2 pi k / 3, sin 2 pi k / 3)
  // k when |z - root(k)| <= closed_form_match, else unknown_mode.
  static int mode_of(const Vector<2>& z);
};

struct FourBarLengths {
  double crank = 2.0, coupler = 7.0, rocker = 5.0, ground = 6.0;  // Grashof: 2 + 7 <= 5 + 6, crank-rocker
};

// O2 = (0, 0), O4 = (ground, 0), A = crank u(phi), B = A + coupler u(theta3) = O4 + rocker u(theta4):
// f = A + coupler u(theta3) - O4 - rocker u(theta4). det J = coupler rocker sin(theta3 - theta4):
// singular (the toggle) where coupler and rocker are in line, theta3 - theta4 = k pi.
class FourBar {
 public:
  static constexpr int size = 2;
  explicit FourBar(double crank_angle, FourBarLengths lengths = {});
  int dimension() const { return 2; }
  void residual(const Vector<2>& theta, Vector<2>& f) const;
  void jacobian(const Vector<2>& theta, Matrix<2>& J) const;
  // Mode 0: B to the left of A -> O4 (side +1); mode 1: to its right (side -1). Checked against
  // circle_intersection() for that side; unknown_mode when they differ.
  int mode_of(const Vector<2>& theta) const;
  // The closed-form angles (theta3, theta4) of a mode.
  Vector<2> closed_form(int mode) const;
  static int side_of_mode(int mode) { return mode == 0 ? 1 : -1; }

 private:
  FourBarLengths lengths_;
  Eigen::Vector2d A_, O4_;
};

// The Jansen leg's 16 branches: bit k of a mode is set when dyad k's joint lies to the left of its
// line of centres (side +1), for the dyads B (A, P1), C (B, P1), D (A, P1), E (C, D) in that order,
// the order of JansenLeg::closed_form_joints().
class JansenModes {
 public:
  explicit JansenModes(double crank_angle, mechanisms::JansenLengths lengths = {});
  static constexpr int count = 16;
  // The mode of converged angles, checked against the closed form of that branch (joints B, C, D, E
  // within closed_form_match); unknown_mode otherwise.
  int mode_of(const Vector<8>& theta) const;
  // The joints B, C, D, E of a branch by circle intersections; false when a dyad cannot close.
  bool closed_form(int mode, std::array<Eigen::Vector2d, 4>& joints) const;
  // The angles theta1 ... theta8 of a branch, each within pi of `near` (false when it cannot close).
  bool closed_form_angles(int mode, const Vector<8>& near, Vector<8>& theta) const;
  static int mode_of_sides(int side_B, int side_C, int side_D, int side_E);
  static std::string label(int mode);  // "B- C- D+ E-"
  static int seed_mode();               // the seed's branch (JansenLeg::side_B ... side_E)

 private:
  std::array<Eigen::Vector2d, 4> joints_of(const Vector<8>& theta) const;
  mechanisms::JansenLengths lengths_;
  Eigen::Vector2d A_, P1_;
};

}  // namespace numlab::basins
