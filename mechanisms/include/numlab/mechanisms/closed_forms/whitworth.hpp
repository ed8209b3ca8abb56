#pragma once
// The Whitworth quick-return (mechanisms/models/whitworth.toml) in closed form. The crank O2-A is
// longer than the pivot distance |O2 O4|, so the slotted link O4-B, in whose slot the block at A
// slides, turns fully too, unevenly; the link B-C drives the ram C along a horizontal ground slider.

#include "numlab/mechanisms/closed_forms/motion.hpp"

namespace numlab::mechanisms::closed_forms {

struct Whitworth {
  Eigen::Vector2d O2 = Eigen::Vector2d::Zero();  // the crank's pivot
  Eigen::Vector2d O4 = Eigen::Vector2d::Zero();  // the slotted link's pivot
  double crank = 0.0;                            // |O2 A|, > |O2 O4|
  double slot = 0.0;                             // |O4 B|
  double rod = 0.0;                              // |B C|, > slot + |ram_height - O4_y| so that C always exists
  double ram_height = 0.0;                       // the ram's line y = h
  int ram_side = 1;                              // C to the right of B (+1) or to the left (-1)
};

struct WhitworthPose {
  PointMotion A, B, C;
  AngleMotion crank, slot, rod;  // O2 -> A, O4 -> B, B -> C
  double slide = 0.0;            // |O4 A|: the block's place in the slot
};

// The pose at crank angle t (radians from +x), derivatives per radian of crank:
//  1.-3. A = O2 + r e(t); the slotted link points at A, phi = atan2(A - O4); B = O4 + R e(phi): the
//     inverted slider-crank O2-A with the slot O4-B as its rocker (inverted_slider_crank.hpp);
//  4. the ram: w = h - B_y, q = sqrt(l^2 - w^2), C = (B_x + side q, h), with
//     q' = -w w' / q, q'' = -(w'^2 + w w'') / q - w^2 w'^2 / q^3 (w' = -B_y', w'' = -B_y'');
//  5. the rod's angle psi = atan2(w, side q): psi' = side w' / q, psi'' = side (w'' q - w' q') / q^2.
WhitworthPose whitworth(const Whitworth& mechanism, double t);

// With the ram's line through O4 (h = O4_y) the ram stands still exactly when the slotted link lies
// along it (phi = 0 or pi: C_x' = -R sin phi (1 + R cos phi / q) vanishes only there), that is when
// A crosses the line y = O4_y: sin t = (O4_y - O2_y) / r. The crank turns pi + 2 beta one way between
// the two and pi - 2 beta the other, beta = asin(|O4_y - O2_y| / r): time ratio
// (pi + 2 beta) / (pi - 2 beta). Throws std::invalid_argument for a ram line not through O4.
QuickReturn whitworth_quick_return(const Whitworth& mechanism);

}  // namespace numlab::mechanisms::closed_forms
