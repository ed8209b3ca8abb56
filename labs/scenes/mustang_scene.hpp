#pragma once
// Scenes of the Mustang roof linkage as SVG: one pose with the path of the roof tip P12, and the
// sweep animated (SMIL, plays in a browser). The three major (bent) links are drawn heavier, in
// seed 003's colours: 2-4-6-7 red, 5-6-8-9 magenta, 9-11-12 cyan; the minor links thin and black.

#include <string>

#include "numlab/mechanisms/mustang_sweep.hpp"

namespace numlab::cli {

std::string mustang_pose_svg(const mechanisms::MustangSweep& sweep, std::size_t pose);
std::string mustang_animation_svg(const mechanisms::MustangSweep& sweep, double seconds);

}  // namespace numlab::cli
