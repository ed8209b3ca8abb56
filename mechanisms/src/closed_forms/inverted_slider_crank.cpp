// The inverted slider-crank in closed form (closed_forms/inverted_slider_crank.hpp).

#include "numlab/mechanisms/closed_forms/inverted_slider_crank.hpp"

#include <cmath>

namespace numlab::mechanisms::closed_forms {

InvertedSliderCrankPose inverted_slider_crank(const InvertedSliderCrank& m, double t) {
  InvertedSliderCrankPose pose;
  // 1. The crank.
  pose.crank = crank_angle(t);
  pose.A = on_circle(m.O, m.crank, pose.crank);
  // 2. The rocker's direction, from B to A.
  const Eigen::Vector2d u = pose.A.p - m.B;
  pose.rocker = direction_of(u, pose.A.v, pose.A.a);
  // 3. Its far end.
  pose.C = on_circle(m.B, m.rocker, pose.rocker);
  // 4. The block's travel along the rocker.
  const double s = u.norm(), along = u.dot(pose.A.v);
  pose.slide = s;
  pose.slide_rate = along / s;
  pose.slide_acceleration = (pose.A.v.squaredNorm() + u.dot(pose.A.a)) / s - along * along / (s * s * s);
  return pose;
}

QuickReturn inverted_slider_crank_quick_return(const InvertedSliderCrank& m) {
  const Eigen::Vector2d ground = m.B - m.O;
  const double towards_b = std::atan2(ground.y(), ground.x());
  const double gamma = std::acos(m.crank / ground.norm());
  return {in_one_turn(towards_b - gamma), in_one_turn(towards_b + gamma), (pi - gamma) / gamma};
}

}  // namespace numlab::mechanisms::closed_forms
