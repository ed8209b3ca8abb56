#pragma once
// Three small mechanisms, one per new item of the linkage format, each with its closed form written
// from its geometry (never from the model's rows), at any length scale k:
//   - the inverted slider-crank: crank O-A (r), the block at A sliding in the slot of the rocker B-C
//     (ground pivot B), the slot `e` to the left of B -> C: the rocker's angle phi = alpha - asin(e / rho),
//     alpha and rho the angle and length of A - B;
//   - the hydraulic boom: a bar O-P-T on one line (a collinear [[body]], T on P's extension), pushed
//     by an actuator from the ground joint G to P: the law of cosines in O, G, P;
//   - the four-bar driven by a motor at its moving joint A (the angle from A->O to A->B): the law of
//     cosines gives |OB|, then B and A by circle intersections.

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <map>
#include <string>

namespace numlab::mechanisms::testing {

inline constexpr double pi = 3.141592653589793238462643383279502884;
inline constexpr double deg = pi / 180.0;

using Joints = std::map<std::string, Eigen::Vector2d>;

inline Eigen::Vector2d polar(double radius, double angle) { return radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)); }

// The intersection of the circles (c1, r1) and (c2, r2) to the left of c1 -> c2 (side +1) or right (-1).
inline Eigen::Vector2d circles(const Eigen::Vector2d& c1, double r1, const Eigen::Vector2d& c2, double r2, int side) {
  const Eigen::Vector2d d = c2 - c1;
  const double D = d.norm(), a = (r1 * r1 - r2 * r2 + D * D) / (2.0 * D), h = std::sqrt(r1 * r1 - a * a);
  const Eigen::Vector2d u = d / D, n(-u.y(), u.x());
  return c1 + a * u + side * h * n;
}

// --- the inverted slider-crank: O = (0, 0), B = (3k, 0), crank 1k, rocker 5k, slot offset e k ---
struct InvertedSliderCrank {
  double k = 1.0, e = 0.0;
  Joints at(double crank_rad) const {
    const Eigen::Vector2d O(0, 0), B(3 * k, 0), A = polar(k, crank_rad), w = A - B;
    const double phi = std::atan2(w.y(), w.x()) - std::asin(e * k / w.norm());
    return {{"O", O}, {"B", B}, {"A", A}, {"C", B + polar(5 * k, phi)}};
  }
  std::string text(double crank_deg, const std::string& loads = "") const {
    const Joints j = at(crank_deg * deg);
    return fmt::format(R"([linkage]
name = "inverted-slider-crank"

[ground]
O = [0.0, 0.0]
B = [{0:.17g}, 0.0]

[joints]
A = [{1:.17g}, {2:.17g}]
C = [{3:.17g}, {4:.17g}]

[[link]]
joints = ["O", "A"]
length = {5:.17g}

[[link]]
name = "rocker"
joints = ["B", "C"]
length = {6:.17g}

[[slider]]
joint = "A"
line = ["B", "C"]
offset = {7:.17g}

[driver]
type = "crank"
pivot = "O"
joint = "A"
angle = {8:.17g}
{9})",
                       3 * k, j.at("A").x(), j.at("A").y(), j.at("C").x(), j.at("C").y(), k, 5 * k, e * k, crank_deg, loads);
  }
};

// --- the boom: O = (0, 0), G = (a k, 0), the bar O-P-T (|OP| = b k, |OT| = 1.5 b k), the actuator G-P ---
struct Boom {
  double k = 1.0, a = 1.0, b = 2.0;
  Joints at(double s) const {  // s: the actuator's length (file units)
    const double A = a * k, B = b * k, beta = std::acos((A * A + B * B - s * s) / (2.0 * A * B));
    const Eigen::Vector2d P = polar(B, beta);
    return {{"O", {0, 0}}, {"G", {A, 0}}, {"P", P}, {"T", 1.5 * P}};
  }
  std::string text(double s, const std::string& loads = "") const {
    const Joints j = at(s);
    return fmt::format(R"([linkage]
name = "boom"

[ground]
O = [0.0, 0.0]
G = [{0:.17g}, 0.0]

[joints]
P = [{1:.17g}, {2:.17g}]
T = [{3:.17g}, {4:.17g}]

[[body]]
name = "boom"
joints = ["O", "P", "T"]
local = [[0.0, 0.0], [{5:.17g}, 0.0], [{6:.17g}, 0.0]]

[driver]
type = "actuator"
joints = ["G", "P"]
length = {7:.17g}
{8})",
                       a * k, j.at("P").x(), j.at("P").y(), j.at("T").x(), j.at("T").y(), b * k, 1.5 * b * k, s, loads);
  }
};

// --- the motor four-bar: O = (0, 0), Q = (4.5k, 0), crank O-A 1.5k, coupler A-B 4k, rocker Q-B 3.5k;
// the motor at A from O to B (B above the ground line) ---
struct MotorFourBar {
  double k = 1.0;
  Joints at(double motor_rad) const {
    const double a = 1.5 * k, b = 4.0 * k, c = 3.5 * k;
    const Eigen::Vector2d O(0, 0), Q(4.5 * k, 0);
    const double OB = std::sqrt(a * a + b * b - 2.0 * a * b * std::cos(motor_rad));
    const Eigen::Vector2d B = circles(O, OB, Q, c, +1);
    // A on the circles (O, a) and (B, b), on the side where the angle from A->O to A->B is the motor's:
    // (O - A) x (B - A) = B x A, positive (sin t > 0) when A is to the left of O -> B.
    const Eigen::Vector2d A = circles(O, a, B, b, std::sin(motor_rad) > 0 ? +1 : -1);
    return {{"O", O}, {"Q", Q}, {"A", A}, {"B", B}};
  }
  std::string text(double motor_deg, const std::string& loads = "") const {
    const Joints j = at(motor_deg * deg);
    return fmt::format(R"([linkage]
name = "motor-four-bar"

[ground]
O = [0.0, 0.0]
Q = [{0:.17g}, 0.0]

[joints]
A = [{1:.17g}, {2:.17g}]
B = [{3:.17g}, {4:.17g}]

[[link]]
name = "crank"
joints = ["O", "A"]
length = {5:.17g}

[[link]]
name = "coupler"
joints = ["A", "B"]
length = {6:.17g}

[[link]]
name = "rocker"
joints = ["Q", "B"]
length = {7:.17g}

[driver]
type = "motor"
pivot = "A"
from = "O"
joint = "B"
angle = {8:.17g}
{9})",
                       4.5 * k, j.at("A").x(), j.at("A").y(), j.at("B").x(), j.at("B").y(), 1.5 * k, 4 * k, 3.5 * k,
                       motor_deg, loads);
  }
};

}  // namespace numlab::mechanisms::testing
