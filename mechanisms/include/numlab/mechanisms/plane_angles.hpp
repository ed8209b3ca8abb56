#pragma once
// Unit vectors and directions in the plane, angles in radians: what the closed-form linkage
// solutions, the linkage model and the basin maps' linkage systems build poses from.

#include <Eigen/Core>
#include <cmath>

namespace numlab::mechanisms {

// The unit vector at `angle` from the x axis.
inline Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// The angle of the direction from `from` to `to`, in (-pi, pi].
inline double direction(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return std::atan2(to.y() - from.y(), to.x() - from.x());
}

}  // namespace numlab::mechanisms
