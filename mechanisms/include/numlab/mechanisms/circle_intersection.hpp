#pragma once
// Where two circles meet: the building block of every closed-form (dyadic) linkage solution.

#include <Eigen/Core>
#include <optional>

namespace numlab::mechanisms {

// The intersection of circle(first, first_radius) and circle(second, second_radius) on one side of
// the line first -> second: side = +1 to its left, -1 to its right. Nothing when the circles do not
// meet (the dyad cannot assemble) or are concentric.
std::optional<Eigen::Vector2d> circle_intersection(const Eigen::Vector2d& first, double first_radius,
                                                   const Eigen::Vector2d& second, double second_radius, int side);

// The side (+1 left, -1 right) of `point` relative to the line first -> second.
int side_of(const Eigen::Vector2d& first, const Eigen::Vector2d& second, const Eigen::Vector2d& point);

}  // namespace numlab::mechanisms
