// Closed forms: the pieces every model's closed form is built from (closed_forms/motion.hpp).

#include "numlab/mechanisms/closed_forms/motion.hpp"

#include <cmath>

namespace numlab::mechanisms::closed_forms {

double cross(const Eigen::Vector2d& x, const Eigen::Vector2d& y) { return x.x() * y.y() - x.y() * y.x(); }

Eigen::Vector2d unit(double a) { return {std::cos(a), std::sin(a)}; }

Eigen::Vector2d unit_normal(double a) { return {-std::sin(a), std::cos(a)}; }

AngleMotion direction_of(const Eigen::Vector2d& u, const Eigen::Vector2d& du, const Eigen::Vector2d& ddu) {
  const double length2 = u.squaredNorm();
  const double omega = cross(u, du) / length2;
  return {std::atan2(u.y(), u.x()), omega, cross(u, ddu) / length2 - 2.0 * u.dot(du) * omega / length2};
}

double in_one_turn(double a) { return a - 2.0 * pi * std::floor(a / (2.0 * pi)); }

PointMotion on_circle(const Eigen::Vector2d& centre, double radius, const AngleMotion& angle) {
  const Eigen::Vector2d e = unit(angle.angle), n = unit_normal(angle.angle);
  return {centre + radius * e, radius * angle.omega * n, radius * angle.alpha * n - radius * angle.omega * angle.omega * e};
}

}  // namespace numlab::mechanisms::closed_forms
