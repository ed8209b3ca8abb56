#pragma once
// Scenes of any linkage read from a description file, as SVG (no dependency): one pose with the
// paths of the moving joints over the sweep, optionally with velocity arrows, and an animated sweep
// (SMIL <animate>, plays in a browser).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::cli {

// What a scene shows beyond the linkage itself.
struct LinkageSceneOptions {
  bool velocity_arrows = false;  // the pose: each moving joint's velocity as an arrow
  std::vector<int> paths;        // joints whose paths are drawn, highlighted; empty: every moving joint's
  std::string paths_from;        // who chose them, for the caption ("--path", "the file's trace")
  std::string pose_reason;       // why this pose, for the caption (e.g. "the best-conditioned pose")
};

// The linkage at sweep.poses[pose] (a converged pose): links as bars, bodies as filled polygons (a
// body whose points lie on one line as a bar through its outer points), ground joints as fixed
// pivots on hatched ground (ground_drawing.hpp), sliders' lines, joint names placed apart
// (label_placement.hpp); dashed, the path of every moving joint over the converged poses, or only
// those of options.paths. With velocity_arrows, each moving joint's velocity (per radian of crank,
// or per unit of slider travel) as an arrow, scaled so the longest is a fixed share of the picture;
// the caption states the scale.
std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, const LinkageSceneOptions& options);
std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, bool velocity_arrows);

// Every converged pose in turn, `seconds` per pass, repeating; poses that did not assemble are skipped
// (the caption says how many). options.paths as for the pose; the arrows are not drawn.
std::string linkage_animation_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                                  double seconds, const LinkageSceneOptions& options = {});

// The pose --svg draws by default: of the converged poses, the one whose J is best conditioned
// (smallest kappa(J), the first of equals), so never a pose collapsed at a limit or a crossing; the
// first converged pose when none has a finite kappa; nullopt when none converged.
std::optional<std::size_t> best_conditioned_pose(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep);

// The pose whose driver value is `value` (user units, as the CSV's first column prints it: equal
// within 1e-9 of the sweep's step), or nullopt.
std::optional<std::size_t> pose_at(const mechanisms::LinkageSweep& sweep, double value);

}  // namespace numlab::cli
