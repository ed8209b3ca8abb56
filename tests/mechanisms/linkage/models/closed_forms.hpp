#pragma once
// Textbook closed forms the shipped four-bar and slider-crank files are checked against.

#include <cmath>

namespace numlab::mechanisms::testing {

// Freudenstein's equation for a four-bar O-A-B-Q (crank a = |OA|, coupler b = |AB|, rocker
// c = |QB|, ground d = |OQ| along +x): the rocker angle p (of Q -> B) at the crank angle t solves
//   K1 cos p - K2 cos t + K3 = cos(t - p),  K1 = d / a, K2 = d / c, K3 = (a^2 - b^2 + c^2 + d^2) / (2 a c).
// With u = tan(p / 2) it is the quadratic A u^2 + B u + C = 0; sign = +-1 picks the branch.
inline double freudenstein_rocker(double a, double b, double c, double d, double t, int sign) {
  const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2.0 * a * c);
  const double A = std::cos(t) - K1 - K2 * std::cos(t) + K3;
  const double B = -2.0 * std::sin(t);
  const double C = K1 - (K2 + 1.0) * std::cos(t) + K3;
  return 2.0 * std::atan2(-B + sign * std::sqrt(B * B - 4.0 * A * C), 2.0 * A);
}

// The offset slider-crank: crank r about the origin at angle t, rod l, slider on the line y = e.
//   x(t)   = r cos t + sqrt(l^2 - (r sin t - e)^2)
// and its first two derivatives in t (per radian, per radian^2).
struct SliderMotion {
  double x, velocity, acceleration;
};
inline SliderMotion offset_slider_crank(double r, double l, double e, double t) {
  const double h = r * std::sin(t) - e, root = std::sqrt(l * l - h * h);
  const double dh = r * std::cos(t), ddh = -r * std::sin(t);
  return {r * std::cos(t) + root, -r * std::sin(t) - h * dh / root,
          -r * std::cos(t) - (dh * dh + h * ddh) / root - (h * dh) * (h * dh) / (root * root * root)};
}

}  // namespace numlab::mechanisms::testing
