// The hydraulic-cylinder boom in closed form (closed_forms/hydraulic_boom.hpp).

#include "numlab/mechanisms/closed_forms/hydraulic_boom.hpp"

#include <cmath>

namespace numlab::mechanisms::closed_forms {

HydraulicBoomPose hydraulic_boom(const HydraulicBoom& m, double s) {
  HydraulicBoomPose pose;
  // 1. The angle at O of the triangle O, P, B.
  const Eigen::Vector2d ground = m.P - m.O;
  const double g = ground.norm(), b = m.pin;
  const double gamma = std::acos((g * g + b * b - s * s) / (2.0 * g * b));
  const double sin_g = std::sin(gamma), cos_g = std::cos(gamma);
  const double dgamma = s / (g * b * sin_g);
  const double ddgamma = (1.0 - s * cos_g * dgamma / sin_g) / (g * b * sin_g);
  // 2. The boom's angle.
  const double side = m.side >= 0 ? 1.0 : -1.0;
  pose.boom = {std::atan2(ground.y(), ground.x()) + side * gamma, side * dgamma, side * ddgamma};
  // 3. Its points B and T.
  pose.B = on_circle(m.O, b, pose.boom);
  pose.T = on_circle(m.O, m.tip, {pose.boom.angle + m.tip_angle, pose.boom.omega, pose.boom.alpha});
  pose.boom.angle = std::atan2(std::sin(pose.boom.angle), std::cos(pose.boom.angle));
  // 4. The cylinder's direction.
  pose.cylinder = direction_of(pose.B.p - m.P, pose.B.v, pose.B.a);
  return pose;
}

double cylinder_force(const HydraulicBoom& m, const HydraulicBoomPose& pose, const Eigen::Vector2d& tip_force) {
  const Eigen::Vector2d u = (pose.B.p - m.P).normalized();
  return -cross(pose.T.p - m.O, tip_force) / cross(pose.B.p - m.O, u);
}

}  // namespace numlab::mechanisms::closed_forms
