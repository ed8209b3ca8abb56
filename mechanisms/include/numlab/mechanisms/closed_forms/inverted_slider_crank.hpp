#pragma once
// The inverted slider-crank (mechanisms/models/inverted-slider-crank.toml) in closed form: the crank
// O-A turns about O; a block pinned at A slides along the rocker B-C, which turns about the ground
// pivot B, so the rocker always points from B at A. With the crank shorter than |OB| the rocker
// swings to and fro, and faster one way than the other: a quick-return (the crank-shaper's).

#include "numlab/mechanisms/closed_forms/motion.hpp"

namespace numlab::mechanisms::closed_forms {

struct InvertedSliderCrank {
  Eigen::Vector2d O = Eigen::Vector2d::Zero();  // the crank's pivot
  Eigen::Vector2d B = Eigen::Vector2d::Zero();  // the rocker's pivot
  double crank = 0.0;                           // |OA|
  double rocker = 0.0;                          // |BC|, C the rocker's far end
};

struct InvertedSliderCrankPose {
  PointMotion A, C;
  AngleMotion crank, rocker;  // O -> A and B -> C
  double slide = 0.0, slide_rate = 0.0, slide_acceleration = 0.0;  // |BA| (the block on the rocker) and its derivatives
};

// The pose at crank angle t (radians from +x), derivatives per radian of crank:
//  1. A = O + r e(t), A' = r n(t), A'' = -r e(t);
//  2. the rocker points along u = A - B: phi = atan2(u), phi' and phi'' from direction_of();
//  3. C = B + L e(phi);
//  4. the block's place on the rocker s = |u|: s' = u . u' / s, s'' = (u' . u' + u . u'') / s - (u . u')^2 / s^3.
InvertedSliderCrankPose inverted_slider_crank(const InvertedSliderCrank& mechanism, double t);

// The rocker stands still where BA is perpendicular to OA: cos(angle AOB) = r / |OB|, the crank at
// the direction of OB +- gamma, gamma = acos(r / |OB|). Between them the crank turns 2 gamma on B's
// side and 2 pi - 2 gamma on the other: time ratio (pi - gamma) / gamma. Needs r < |OB|.
QuickReturn inverted_slider_crank_quick_return(const InvertedSliderCrank& mechanism);

}  // namespace numlab::mechanisms::closed_forms
