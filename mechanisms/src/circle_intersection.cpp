#include "numlab/mechanisms/circle_intersection.hpp"

#include <cmath>
#include <limits>

namespace numlab::mechanisms {

std::optional<Eigen::Vector2d> circle_intersection(const Eigen::Vector2d& first, double first_radius,
                                                   const Eigen::Vector2d& second, double second_radius, int side) {
  const Eigen::Vector2d between = second - first;
  const double distance = between.norm();
  if (distance == 0.0) return std::nullopt;
  // Along the line of centres, the common chord is `along` from `first`; it is `half_chord` long each way.
  const double along = (first_radius * first_radius - second_radius * second_radius + distance * distance) /
                       (2.0 * distance);
  double half_chord_squared = first_radius * first_radius - along * along;
  // Circles that touch (a dyad on its meeting point) give zero less rounding: that is zero. The
  // rounding of along^2 is a few eps of r1^2 + r2^2 + d^2, times r1 / d through the division.
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() *
                          (first_radius * first_radius + second_radius * second_radius + distance * distance) *
                          (1.0 + first_radius / distance);
  if (half_chord_squared < 0.0 && half_chord_squared >= -rounding) half_chord_squared = 0.0;
  if (!(half_chord_squared >= 0.0)) return std::nullopt;
  const Eigen::Vector2d direction = between / distance;
  const Eigen::Vector2d left(-direction.y(), direction.x());
  return first + along * direction + side * std::sqrt(half_chord_squared) * left;
}

int side_of(const Eigen::Vector2d& first, const Eigen::Vector2d& second, const Eigen::Vector2d& point) {
  const Eigen::Vector2d a = second - first, b = point - first;
  return a.x() * b.y() - a.y() * b.x() >= 0.0 ? 1 : -1;
}

}  // namespace numlab::mechanisms
