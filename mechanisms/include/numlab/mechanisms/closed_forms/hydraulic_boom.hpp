#pragma once
// The hydraulic-cylinder boom (mechanisms/models/hydraulic-boom.toml) in closed form: a rigid boom
// O-B-T pivoted at the ground point O, raised by a cylinder from the ground pivot P to the boom's
// point B whose length s is the driver; a load hangs at the tip T.

#include "numlab/mechanisms/closed_forms/motion.hpp"

namespace numlab::mechanisms::closed_forms {

struct HydraulicBoom {
  Eigen::Vector2d O = Eigen::Vector2d::Zero();  // the boom's ground pivot
  Eigen::Vector2d P = Eigen::Vector2d::Zero();  // the cylinder's ground pivot
  double pin = 0.0;                             // |OB|
  double tip = 0.0;                             // |OT|
  double tip_angle = 0.0;                       // the angle from O -> B to O -> T, radians (CCW +)
  int side = 1;                                 // B to the left (+1) or the right (-1) of O -> P
};

struct HydraulicBoomPose {
  PointMotion B, T;
  AngleMotion boom;      // O -> B
  AngleMotion cylinder;  // P -> B
};

// The pose at cylinder length s, derivatives per unit of length:
//  1. the triangle O, P, B (g = |OP|, b = |OB|, s = |PB|): the angle at O is
//     cos gamma = (g^2 + b^2 - s^2) / (2 g b), gamma' = s / (g b sin gamma),
//     gamma'' = (1 - s cos gamma gamma' / sin gamma) / (g b sin gamma);
//  2. the boom's angle theta = angle(O -> P) + side gamma;
//  3. B = O + b e(theta), T = O + |OT| e(theta + tip angle);
//  4. the cylinder's direction from P to B (direction_of()).
HydraulicBoomPose hydraulic_boom(const HydraulicBoom& mechanism, double s);

// The cylinder's push (N, along P -> B; negative: it pulls) that holds the boom against a constant
// force at T, from the boom's balance of moments about O:
//   (B - O) × (f u) + (T - O) × F = 0,  u = (B - P) / s.
double cylinder_force(const HydraulicBoom& mechanism, const HydraulicBoomPose& pose, const Eigen::Vector2d& tip_force);

}  // namespace numlab::mechanisms::closed_forms
