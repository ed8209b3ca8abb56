#pragma once
// Closed forms of the shipped one-driver models (mechanisms/models/): each mechanism's joints, link
// angles and their first two derivatives, written from its geometry (law of cosines, atan2) and
// differentiated by hand. They share nothing with the linkage solver, so the tests and `numlab
// bench` can hold the description files against them. This header: what they have in common.

#include <Eigen/Core>

namespace numlab::mechanisms::closed_forms {

inline constexpr double pi = 3.141592653589793238462643383279502884;

// A point's position and its first two derivatives in the driver (per radian of crank, or per unit
// of an actuator's length).
struct PointMotion {
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero();
};

// An angle (radians, atan2's range) and its first two derivatives in the driver.
struct AngleMotion {
  double angle = 0.0, omega = 0.0, alpha = 0.0;
};

// The 2-D cross product x × y = x_x y_y - x_y y_x.
double cross(const Eigen::Vector2d& x, const Eigen::Vector2d& y);

// The unit vector at angle a, and the one a quarter turn ahead of it.
Eigen::Vector2d unit(double a);
Eigen::Vector2d unit_normal(double a);

// The direction of a moving vector u (du, ddu its derivatives):
//   theta   = atan2(u_y, u_x)
//   theta'  = (u × u') / |u|^2
//   theta'' = (u × u'') / |u|^2 - 2 (u . u') (u × u') / |u|^4
AngleMotion direction_of(const Eigen::Vector2d& u, const Eigen::Vector2d& du, const Eigen::Vector2d& ddu);

// The point at `radius` from a fixed `centre` along the turning angle:
//   p = c + R e(theta),  p' = R theta' n(theta),  p'' = R theta'' n(theta) - R theta'^2 e(theta)
PointMotion on_circle(const Eigen::Vector2d& centre, double radius, const AngleMotion& angle);

// The angle a, less whole turns, in [0, 2 pi).
double in_one_turn(double a);

// A crank turning with its driver: angle t, omega 1, alpha 0.
inline AngleMotion crank_angle(double t) { return {t, 1.0, 0.0}; }

// The crank angles (radians, [0, 2 pi)) where a quick-return's output stands still, and its time
// ratio: the longer crank travel between them over the shorter.
struct QuickReturn {
  double toggle_1 = 0.0, toggle_2 = 0.0;
  double time_ratio = 0.0;
};

}  // namespace numlab::mechanisms::closed_forms
