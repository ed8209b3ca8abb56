#pragma once
// Scenes of the Jansen leg as SVG (no dependency): one pose with the whole foot path, an animated
// cycle (SMIL <animate>, plays in a browser), and the four-legged beest built from one solved cycle.

#include <string>

#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::cli {

// The leg at poses[pose], the foot path of all poses, the crank circle and the fixed pivots.
std::string jansen_pose_svg(const mechanisms::JansenSweep& sweep, std::size_t pose);

// Every pose in turn, `seconds` per pass through the sweep, repeating.
std::string jansen_animation_svg(const mechanisms::JansenSweep& sweep, double seconds);

// Seed 000's beest: front pair and hind pair, each pair's second leg half a cycle behind its
// first, the hind pair mirrored, all four read from the one cycle in `sweep` (no new solve).
// Needs a sweep of one full turn in equal steps. With `seconds` > 0 it is animated.
std::string beest_svg(const mechanisms::JansenSweep& sweep, double seconds);

}  // namespace numlab::cli
