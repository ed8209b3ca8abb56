#include "numlab/mechanisms/jansen_leg.hpp"

#include <cmath>
#include <numbers>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/plane_angles.hpp"

namespace numlab::mechanisms {

namespace {
// `angle` shifted by a multiple of 2 pi to lie within pi of `near`.
double within_half_turn(double angle, double near) {
  constexpr double turn = 2.0 * std::numbers::pi;
  return angle + turn * std::round((near - angle) / turn);
}
}  // namespace

JansenLeg::JansenLeg(JansenLengths lengths, JansenFootLengths foot)
    : lengths_(lengths),
      foot_(foot),
      // Cosine rule in triangle D-E-F (seed 000 eq 21): c = acos((l8^2 + l9^2 - l10^2) / (2 l8 l9)).
      foot_angle_(std::acos((lengths.l8 * lengths.l8 + foot.l9 * foot.l9 - foot.l10 * foot.l10) /
                            (2.0 * lengths.l8 * foot.l9))) {
  using J = JansenJoint;
  links_ = {{{J::O, J::A, lengths.crank},
             {J::A, J::B, lengths.l1},
             {J::P1, J::B, lengths.l2},
             {J::B, J::C, lengths.l3},
             {J::P1, J::C, lengths.l4},
             {J::C, J::E, lengths.l5},
             {J::A, J::D, lengths.l6},
             {J::P1, J::D, lengths.l7},
             {J::D, J::E, lengths.l8},
             {J::D, J::F, foot.l9},
             {J::E, J::F, foot.l10}}};
}

JansenJoints JansenLeg::joints(double crank_angle, const JansenAngles& theta) const {
  const JansenLengths& L = lengths_;
  JansenJoints p;
  p[at(JansenJoint::O)] = Eigen::Vector2d::Zero();
  p[at(JansenJoint::P1)] = Eigen::Vector2d(-L.b, -L.a);
  p[at(JansenJoint::A)] = L.crank * unit(crank_angle);                                  // eq 15
  p[at(JansenJoint::B)] = p[at(JansenJoint::A)] + L.l1 * unit(theta(0));                 // eq 16
  p[at(JansenJoint::C)] = p[at(JansenJoint::B)] + L.l3 * unit(theta(2));                 // eq 17
  p[at(JansenJoint::D)] = p[at(JansenJoint::P1)] + L.l7 * unit(theta(6));                // eq 18
  p[at(JansenJoint::E)] = p[at(JansenJoint::D)] + L.l8 * unit(theta(7));                 // eq 19
  p[at(JansenJoint::F)] = p[at(JansenJoint::D)] + foot_.l9 * unit(theta(7) + foot_angle_);  // eq 20
  return p;
}

std::optional<JansenJoints> JansenLeg::closed_form_joints(double crank_angle) const {
  const JansenLengths& L = lengths_;
  JansenJoints p;
  p[at(JansenJoint::O)] = Eigen::Vector2d::Zero();
  p[at(JansenJoint::P1)] = Eigen::Vector2d(-L.b, -L.a);
  p[at(JansenJoint::A)] = L.crank * unit(crank_angle);
  const Eigen::Vector2d& P1 = p[at(JansenJoint::P1)];
  const Eigen::Vector2d& A = p[at(JansenJoint::A)];
  const auto B = circle_intersection(A, L.l1, P1, L.l2, side_B);
  if (!B) return std::nullopt;
  const auto C = circle_intersection(*B, L.l3, P1, L.l4, side_C);
  const auto D = circle_intersection(A, L.l6, P1, L.l7, side_D);
  if (!C || !D) return std::nullopt;
  const auto E = circle_intersection(*C, L.l5, *D, L.l8, side_E);
  if (!E) return std::nullopt;
  p[at(JansenJoint::B)] = *B;
  p[at(JansenJoint::C)] = *C;
  p[at(JansenJoint::D)] = *D;
  p[at(JansenJoint::E)] = *E;
  // F on the rigid triangle: D-F turned by c from D-E.
  p[at(JansenJoint::F)] = *D + foot_.l9 * unit(direction(*D, *E) + foot_angle_);
  return p;
}

JansenAngles JansenLeg::angles_of(const JansenJoints& p, const JansenAngles& near) {
  using J = JansenJoint;
  const std::array<std::pair<J, J>, 8> ends = {{{J::A, J::B}, {J::P1, J::B}, {J::B, J::C}, {J::P1, J::C},
                                                 {J::C, J::E}, {J::A, J::D}, {J::P1, J::D}, {J::D, J::E}}};
  JansenAngles theta;
  for (int k = 0; k < 8; ++k) {
    theta(k) = within_half_turn(direction(p[at(ends[k].first)], p[at(ends[k].second)]), near(k));
  }
  return theta;
}

JansenRates JansenLeg::rates(double crank_angle, const JansenAngles& theta) const {
  const JansenClosureOf<TableSines> closure(crank_angle, lengths_);  // the sweep's closure
  JansenClosure::Vector f;
  JansenClosure::Matrix J;
  closure.residual_and_jacobian(theta, f, J);
  // df/d(theta_i): the crank term li u(theta_i) appears in every equation; its sine rows (even
  // index) change by li cos(theta_i), its cosine rows by -li sin(theta_i).
  JansenClosure::Vector crank_derivative;
  for (int row = 0; row < 8; row += 2) {
    crank_derivative(row) = lengths_.crank * std::cos(crank_angle);
    crank_derivative(row + 1) = -lengths_.crank * std::sin(crank_angle);
  }
  const auto solved = linalg::gauss_elimination<8>(J, -crank_derivative);
  JansenRates rates{solved.x, Eigen::Vector2d::Zero(), 0.0, solved.status};
  if (solved.status != Status::converged) return rates;
  // F = P1 + l7 u(theta7) + l9 u(theta8 + c): differentiate each unit vector, u' = (-sin, cos).
  auto turning = [](double angle) { return Eigen::Vector2d(-std::sin(angle), std::cos(angle)); };
  rates.foot_velocity = lengths_.l7 * turning(theta(6)) * rates.angle_rates(6) +
                        foot_.l9 * turning(theta(7) + foot_angle_) * rates.angle_rates(7);
  rates.foot_speed = rates.foot_velocity.norm();
  return rates;
}

double JansenLeg::worst_length_error(const JansenJoints& p) const {
  double worst = 0.0;
  for (const JansenLink& link : links_) {
    worst = std::max(worst, std::abs((p[at(link.to)] - p[at(link.from)]).norm() - link.length));
  }
  return worst;
}

int JansenLeg::triangle_orientation(const JansenJoints& p) {
  const int upper = side_of(p[at(JansenJoint::P1)], p[at(JansenJoint::B)], p[at(JansenJoint::C)]);
  const int foot = side_of(p[at(JansenJoint::D)], p[at(JansenJoint::E)], p[at(JansenJoint::F)]);
  return upper * foot;
}

}  // namespace numlab::mechanisms
