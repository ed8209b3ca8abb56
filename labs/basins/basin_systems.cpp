#include "basins/basin_systems.hpp"

#include <cmath>

#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/plane_angles.hpp"

namespace numlab::basins {

using mechanisms::direction;
using mechanisms::unit;

// ---- z^3 - 1

void CubeRoots::residual(const Vector<2>& z, Vector<2>& f) const {
  const double x = z(0), y = z(1);
  f << x * x * x - 3 * x * y * y - 1, 3 * x * x * y - y * y * y;
}

void CubeRoots::jacobian(const Vector<2>& z, Matrix<2>& J) const {
  const double x = z(0), y = z(1);
  const double a = 3 * (x * x - y * y), b = 6 * x * y;
  J << a, -b, b, a;
}

Eigen::Vector2d CubeRoots::root(int k) { return unit(2 * std::numbers::pi * k / 3); }

int CubeRoots::mode_of(const Vector<2>& z) {
  for (int k = 0; k < 3; ++k) {
    if ((z - root(k)).norm() <= closed_form_match) return k;
  }
  return nonlinear::unknown_mode;
}

// ---- the four-bar

FourBar::FourBar(double crank_angle, FourBarLengths lengths)
    : lengths_(lengths), A_(lengths.crank * unit(crank_angle)), O4_(lengths.ground, 0.0) {}

void FourBar::residual(const Vector<2>& theta, Vector<2>& f) const {
  f = A_ + lengths_.coupler * unit(theta(0)) - O4_ - lengths_.rocker * unit(theta(1));
}

void FourBar::jacobian(const Vector<2>& theta, Matrix<2>& J) const {
  J << -lengths_.coupler * std::sin(theta(0)), lengths_.rocker * std::sin(theta(1)),
       lengths_.coupler * std::cos(theta(0)), -lengths_.rocker * std::cos(theta(1));
}

int FourBar::mode_of(const Vector<2>& theta) const {
  const Eigen::Vector2d B = A_ + lengths_.coupler * unit(theta(0));
  const int mode = mechanisms::side_of(A_, O4_, B) > 0 ? 0 : 1;
  const auto exact = mechanisms::circle_intersection(A_, lengths_.coupler, O4_, lengths_.rocker, side_of_mode(mode));
  return exact && (B - *exact).norm() <= closed_form_match ? mode : nonlinear::unknown_mode;
}

Vector<2> FourBar::closed_form(int mode) const {
  const auto B = mechanisms::circle_intersection(A_, lengths_.coupler, O4_, lengths_.rocker, side_of_mode(mode));
  if (!B) return Vector<2>::Constant(std::nan(""));
  return {direction(A_, *B), direction(O4_, *B)};
}

// ---- the Jansen leg

JansenModes::JansenModes(double crank_angle, mechanisms::JansenLengths lengths)
    : lengths_(lengths), A_(lengths.crank * unit(crank_angle)), P1_(-lengths.b, -lengths.a) {}

std::array<Eigen::Vector2d, 4> JansenModes::joints_of(const Vector<8>& theta) const {
  const Eigen::Vector2d B = A_ + lengths_.l1 * unit(theta(0));
  const Eigen::Vector2d C = B + lengths_.l3 * unit(theta(2));
  const Eigen::Vector2d D = P1_ + lengths_.l7 * unit(theta(6));
  const Eigen::Vector2d E = D + lengths_.l8 * unit(theta(7));
  return {B, C, D, E};
}

int JansenModes::mode_of_sides(int side_B, int side_C, int side_D, int side_E) {
  return (side_B > 0 ? 1 : 0) | (side_C > 0 ? 2 : 0) | (side_D > 0 ? 4 : 0) | (side_E > 0 ? 8 : 0);
}

int JansenModes::seed_mode() {
  using Leg = mechanisms::JansenLeg;
  return mode_of_sides(Leg::side_B, Leg::side_C, Leg::side_D, Leg::side_E);
}

std::string JansenModes::label(int mode) {
  std::string text;
  const char names[] = {'B', 'C', 'D', 'E'};
  for (int k = 0; k < 4; ++k) {
    if (k > 0) text += ' ';
    text += names[k];
    text += (mode >> k) & 1 ? '+' : '-';
  }
  return text;
}

bool JansenModes::closed_form(int mode, std::array<Eigen::Vector2d, 4>& joints) const {
  const auto side = [mode](int k) { return (mode >> k) & 1 ? 1 : -1; };
  using mechanisms::circle_intersection;
  const auto B = circle_intersection(A_, lengths_.l1, P1_, lengths_.l2, side(0));
  if (!B) return false;
  const auto C = circle_intersection(*B, lengths_.l3, P1_, lengths_.l4, side(1));
  const auto D = circle_intersection(A_, lengths_.l6, P1_, lengths_.l7, side(2));
  if (!C || !D) return false;
  const auto E = circle_intersection(*C, lengths_.l5, *D, lengths_.l8, side(3));
  if (!E) return false;
  joints = {*B, *C, *D, *E};
  return true;
}

bool JansenModes::closed_form_angles(int mode, const Vector<8>& near, Vector<8>& theta) const {
  std::array<Eigen::Vector2d, 4> j;
  if (!closed_form(mode, j)) return false;
  // JansenLeg::angles_of reads the angles off the joints (F is not among them).
  using Joint = mechanisms::JansenJoint;
  mechanisms::JansenJoints joints;
  joints.fill(Eigen::Vector2d::Zero());
  joints[static_cast<std::size_t>(Joint::P1)] = P1_;
  joints[static_cast<std::size_t>(Joint::A)] = A_;
  joints[static_cast<std::size_t>(Joint::B)] = j[0];
  joints[static_cast<std::size_t>(Joint::C)] = j[1];
  joints[static_cast<std::size_t>(Joint::D)] = j[2];
  joints[static_cast<std::size_t>(Joint::E)] = j[3];
  theta = mechanisms::JansenLeg::angles_of(joints, near);
  return true;
}

int JansenModes::mode_of(const Vector<8>& theta) const {
  const auto [B, C, D, E] = joints_of(theta);
  using mechanisms::side_of;
  const int mode = mode_of_sides(side_of(A_, P1_, B), side_of(B, P1_, C), side_of(A_, P1_, D), side_of(C, D, E));
  std::array<Eigen::Vector2d, 4> exact;
  if (!closed_form(mode, exact)) return nonlinear::unknown_mode;
  const std::array<Eigen::Vector2d, 4> reached = {B, C, D, E};
  for (int k = 0; k < 4; ++k) {
    if ((reached[k] - exact[k]).norm() > closed_form_match) return nonlinear::unknown_mode;
  }
  return mode;
}

}  // namespace numlab::basins
