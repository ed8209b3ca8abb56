#pragma once
// Crank angles as the sweeps use them. A crank angle and the same angle a whole number of turns
// away give the same pose, so a sweep walks to the nearest of them, never through the turns
// between (`--crank 1e9` once walked 1e9 degrees), and solves in radians from the angle reduced to
// within a turn (std::fmod is exact, so 1e300 degrees is still a definite angle).

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace numlab::mechanisms {

// One degree in radians: 45.0 * degrees is 45 degrees in radians, theta / degrees is theta in degrees.
inline constexpr double degrees = std::numbers::pi / 180.0;

// deg reduced to (-360, 360) by whole turns, in radians. deg itself when |deg| < 360.
inline double crank_radians(double deg) { return std::fmod(deg, 360.0) * degrees; }

// The angle a whole number of turns from deg that lies within half a turn of centre (degrees):
// deg itself when it already lies there and |deg| < 360.
inline double nearest_turn(double deg, double centre) {
  const double within_turn = std::fmod(deg, 360.0);
  return within_turn - 360.0 * std::round((within_turn - centre) / 360.0);
}

// The number of poses start, start + step, ... up to stop (degrees). Throws std::invalid_argument
// for a step of zero, one that points away from stop, a bound that is not finite, or more than
// max_sweep_poses poses.
inline constexpr int max_sweep_poses = 1000000;
inline int sweep_pose_count(double start_deg, double stop_deg, double step_deg) {
  if (!(step_deg != 0.0) || !std::isfinite(start_deg) || !std::isfinite(stop_deg) || !std::isfinite(step_deg) ||
      (stop_deg - start_deg) * step_deg < 0.0) {
    throw std::invalid_argument("sweep " + std::to_string(start_deg) + ":" + std::to_string(stop_deg) + ":" +
                                std::to_string(step_deg) + " does not step from its start towards its stop");
  }
  const double count = std::floor((stop_deg - start_deg) / step_deg + 1e-9) + 1.0;
  if (!(count <= max_sweep_poses)) {
    throw std::invalid_argument("sweep " + std::to_string(start_deg) + ":" + std::to_string(stop_deg) + ":" +
                                std::to_string(step_deg) + " has more than " + std::to_string(max_sweep_poses) +
                                " poses");
  }
  return static_cast<int>(count);
}

}  // namespace numlab::mechanisms
