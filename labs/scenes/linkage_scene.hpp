#pragma once
// Scenes of any linkage read from a description file, as SVG (no dependency): one pose with the
// paths of the moving joints over the sweep, optionally with velocity arrows, and an animated sweep
// (SMIL <animate>, plays in a browser).

#include <cstddef>
#include <string>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::cli {

// The linkage at sweep.poses[pose] (a converged pose): links as bars, bodies as filled polygons,
// ground joints as fixed pivots, sliders' lines, joint names; dashed, the path of every moving joint
// over the converged poses. With `velocity_arrows`, each moving joint's velocity (per radian of
// crank, or per unit of slider travel) as an arrow, scaled so the longest is a fixed share of the
// picture; the caption states the scale.
std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, bool velocity_arrows);

// Every converged pose in turn, `seconds` per pass, repeating; poses that did not assemble are skipped
// (the caption says how many).
std::string linkage_animation_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                                  double seconds);

}  // namespace numlab::cli
