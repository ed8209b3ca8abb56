// Watt's straight-line linkage in closed form (closed_forms/watt_linkage.hpp).

#include "numlab/mechanisms/closed_forms/watt_linkage.hpp"

#include <cmath>

namespace numlab::mechanisms::closed_forms {

WattPose watt_linkage(const WattLinkage& m, double t) {
  WattPose pose;
  const double a = m.rocker_1, b = m.coupler, c = m.rocker_2;
  // 1. The driven rocker.
  pose.rocker_1 = crank_angle(t);
  pose.B = on_circle(m.O1, a, pose.rocker_1);
  // 2. The triangle B, C, O2: the coupler's and the second rocker's angles.
  const Eigen::Vector2d u = m.O2 - pose.B.p;
  const double D = u.norm();
  const double beta = std::acos((b * b + D * D - c * c) / (2.0 * b * D));
  const double t3 = std::atan2(u.y(), u.x()) + (m.side >= 0 ? 1.0 : -1.0) * beta;
  const Eigen::Vector2d C = pose.B.p + b * unit(t3);
  const double t4 = std::atan2(C.y() - m.O2.y(), C.x() - m.O2.x());
  // 3. Velocity.
  const double w3 = a * std::sin(t4 - t) / (b * std::sin(t3 - t4));
  const double w4 = a * std::sin(t - t3) / (c * std::sin(t4 - t3));
  // 4. Acceleration.
  const Eigen::Vector2d column_3 = b * unit_normal(t3), column_4 = -c * unit_normal(t4);
  const Eigen::Vector2d r = a * unit(t) + b * w3 * w3 * unit(t3) - c * w4 * w4 * unit(t4);
  const double det = cross(column_3, column_4);
  pose.coupler = {std::atan2(std::sin(t3), std::cos(t3)), w3, cross(r, column_4) / det};
  pose.rocker_2 = {t4, w4, cross(column_3, r) / det};
  pose.C = on_circle(m.O2, c, pose.rocker_2);
  // 5. The coupler's point M.
  const double f = m.fraction;
  pose.M = {pose.B.p + f * (pose.C.p - pose.B.p), pose.B.v + f * (pose.C.v - pose.B.v), pose.B.a + f * (pose.C.a - pose.B.a)};
  return pose;
}

}  // namespace numlab::mechanisms::closed_forms
