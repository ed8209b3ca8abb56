#pragma once
// Watt's straight-line linkage (mechanisms/models/watt-straight-line.toml) in closed form: two
// rockers O1-B and O2-C and the coupler B-C between them, a four-bar whose coupler's midpoint M runs
// nearly straight while the rockers swing a little either side of parallel. The first rocker is the
// driver.

#include "numlab/mechanisms/closed_forms/motion.hpp"

namespace numlab::mechanisms::closed_forms {

struct WattLinkage {
  Eigen::Vector2d O1 = Eigen::Vector2d::Zero();  // the driven rocker's pivot
  Eigen::Vector2d O2 = Eigen::Vector2d::Zero();  // the other rocker's pivot
  double rocker_1 = 0.0;                         // |O1 B| (a)
  double coupler = 0.0;                          // |B C| (b)
  double rocker_2 = 0.0;                         // |O2 C| (c)
  double fraction = 0.5;                         // M = B + fraction (C - B): 0.5, the midpoint
  int side = -1;                                 // C to the left (+1) or the right (-1) of B -> O2
};

struct WattPose {
  PointMotion B, C, M;
  AngleMotion rocker_1, coupler, rocker_2;  // O1 -> B, B -> C, O2 -> C
};

// The pose at the driven rocker's angle t (radians from +x), derivatives per radian of it (the
// vector loop a e(t2) + b e(t3) - c e(t4) = O2 - O1, differentiated, solved by Cramer's rule):
//  1. B = O1 + a e(t);
//  2. the triangle B, C, O2 (D = |O2 - B|): the angle at B is cos beta = (b^2 + D^2 - c^2) / (2 b D),
//     the coupler's angle t3 = angle(B -> O2) + side beta, C = B + b e(t3), t4 = angle(O2 -> C);
//  3. velocity: b w3 n3 - c w4 n4 = -a n2, so w3 = a sin(t4 - t2) / (b sin(t3 - t4)),
//     w4 = a sin(t2 - t3) / (c sin(t4 - t3));
//  4. acceleration: b a3 n3 - c a4 n4 = a e2 + b w3^2 e3 - c w4^2 e4 =: r, by Cramer's rule
//     a3 = (r × (-c n4)) / det, a4 = ((b n3) × r) / det, det = (b n3) × (-c n4);
//  5. M = B + f (C - B) and likewise its derivatives.
WattPose watt_linkage(const WattLinkage& mechanism, double t);

}  // namespace numlab::mechanisms::closed_forms
