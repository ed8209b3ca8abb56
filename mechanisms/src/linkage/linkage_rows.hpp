#pragma once
// Internal to the linkage model and its fast path: the rows of the constraints that join moving
// links (a slider in a moving slot, an actuator, a motor between two links), with their gradients and
// their second derivatives along a motion, derived by hand (docs/linkage-files.md, "The derived
// model"). LinkageModel and linkage_fast_kernels.cpp both read them from here.

#include <Eigen/Core>
#include <cmath>

namespace numlab::mechanisms::detail {

inline double row_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
inline Eigen::Vector2d row_perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

// A joint A in a slot along the line B -> C of a moving body, `offset` to its left:
//   f = (d x r) / |d| - offset,  d = C - B, r = A - B   (length units: A's distance from the slot)
struct LineSlotRow {
  double value = 0.0;
  Eigen::Vector2d dA, dB, dC;  // df/dp_A, df/dp_B, df/dp_C
};
inline LineSlotRow line_slot_row(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, double offset) {
  const Eigen::Vector2d d = c - b, r = a - b;
  const double length = d.norm(), side = row_cross(d, r);
  LineSlotRow row;
  row.value = side / length - offset;
  // 1. d(d x r)/dr = perp(d); d(d x r)/dd = -perp(r); d(1/|d|)/dd = -d / |d|^3.
  row.dA = row_perp(d) / length;
  row.dC = -row_perp(r) / length - side * d / (length * length * length);
  // 2. f depends on B through both d and r, with the opposite sign.
  row.dB = -(row.dA + row.dC);
  return row;
}
// d^2 f / dt^2 with the joints' velocities and no accelerations: the c'' L^-1 terms of f = c / L,
// c = d x r, L = |d|:  f'' = c''/L - 2 c' L'/L^2 + c (2 L'^2 - L L'')/L^3,
// c' = d' x r + d x r', c'' = 2 d' x r', L' = d . d'/L, L'' = (d' . d' - L'^2)/L.
inline double line_slot_second(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                               const Eigen::Vector2d& va, const Eigen::Vector2d& vb, const Eigen::Vector2d& vc) {
  const Eigen::Vector2d d = c - b, r = a - b, dd = vc - vb, dr = va - vb;
  const double L = d.norm(), side = row_cross(d, r);
  const double side1 = row_cross(dd, r) + row_cross(d, dr), side2 = 2.0 * row_cross(dd, dr);
  const double L1 = d.dot(dd) / L, L2 = (dd.squaredNorm() - L1 * L1) / L;
  return side2 / L - 2.0 * side1 * L1 / (L * L) + side * (2.0 * L1 * L1 - L * L2) / (L * L * L);
}

// An actuator between P and Q at length s:  f = |P - Q| - s, gradient (P - Q)/|P - Q|. At zero length
// the direction is undefined, and below sqrt(eps) of the actuator's reference length `scale` rounding
// decides it: there the gradient is taken as zero, so that J is singular and says so (a named
// failure, never a NaN or a direction made of rounding errors).
inline constexpr double actuator_shortest = 1.5e-8;  // ~ sqrt(eps), relative to the reference length
inline Eigen::Vector2d actuator_gradient(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double scale) {
  const Eigen::Vector2d d = p - q;
  const double length = d.norm();
  return length > actuator_shortest * scale ? Eigen::Vector2d(d / length) : Eigen::Vector2d::Zero();
}
// d^2 |d| / dt^2 with no accelerations: (|d'|^2 - (d . d' / |d|)^2) / |d|.
inline double actuator_second(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& vp,
                              const Eigen::Vector2d& vq, double scale) {
  const Eigen::Vector2d d = p - q, dd = vp - vq;
  const double length = d.norm();
  if (!(length > actuator_shortest * scale)) return 0.0;
  const double along = d.dot(dd) / length;
  return (dd.squaredNorm() - along * along) / length;
}

// A motor at A turning B's link against C's: with u = B - A, v = C - A, phi the angle from u to v,
//   f = scale ((u x v) cos t - (u . v) sin t) / (|u| |v|) = scale sin(phi - t)
// (scale a length: f is then in length units, like the crank's rows).
struct MotorRow {
  double value = 0.0;
  Eigen::Vector2d dA, dB, dC;
  double dt = 0.0;  // df/dt
};
inline MotorRow motor_row(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, double t, double scale) {
  const Eigen::Vector2d u = b - a, v = c - a;
  const double norms = u.norm() * v.norm();
  const double sine = (row_cross(u, v) * std::cos(t) - u.dot(v) * std::sin(t)) / norms;    // sin(phi - t)
  const double cosine = (u.dot(v) * std::cos(t) + row_cross(u, v) * std::sin(t)) / norms;  // cos(phi - t)
  MotorRow row;
  row.value = scale * sine;
  // d phi / du = -perp(u)/|u|^2, d phi / dv = perp(v)/|v|^2 (the gradients of the two atan2's).
  row.dB = -scale * cosine * row_perp(u) / u.squaredNorm();
  row.dC = scale * cosine * row_perp(v) / v.squaredNorm();
  row.dA = -(row.dB + row.dC);
  row.dt = -scale * cosine;
  return row;
}
// d^2 f / dt^2 along the motion with t' = 1 and no accelerations: f = scale sin(psi), psi = phi - t,
//   f'' = scale (cos psi psi'' - sin psi psi'^2),  psi' = theta_v' - theta_u' - 1,
//   theta_u' = (u x u')/|u|^2, theta_u'' = -2 (u x u')(u . u')/|u|^4 (u'' = 0), the same for v.
inline double motor_second(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& va,
                           const Eigen::Vector2d& vb, const Eigen::Vector2d& vc, double t, double scale) {
  const Eigen::Vector2d u = b - a, v = c - a, du = vb - va, dv = vc - va;
  const double uu = u.squaredNorm(), vv = v.squaredNorm(), norms = std::sqrt(uu * vv);
  const double sine = (row_cross(u, v) * std::cos(t) - u.dot(v) * std::sin(t)) / norms;
  const double cosine = (u.dot(v) * std::cos(t) + row_cross(u, v) * std::sin(t)) / norms;
  const double turn_u = row_cross(u, du) / uu, turn_v = row_cross(v, dv) / vv;
  const double psi1 = turn_v - turn_u - 1.0;
  const double psi2 = -2.0 * turn_v * v.dot(dv) / vv + 2.0 * turn_u * u.dot(du) / uu;
  return scale * (cosine * psi2 - sine * psi1 * psi1);
}

}  // namespace numlab::mechanisms::detail
