#pragma once
// What a linkage's velocities are per, in words (docs/cli.md): a radian of a crank's or a motor's
// angle, or a unit of a slider's travel or an actuator's length. One place, so the text report,
// the JSON, the SVG caption and the linkage page say the same.

#include <string>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::cli {

// "radian of crank", "radian of motor", "unit of slider travel", "unit of actuator length".
std::string velocity_per(mechanisms::DriverKind kind);

}  // namespace numlab::cli
