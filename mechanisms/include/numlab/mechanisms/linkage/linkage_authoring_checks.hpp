#pragma once
// Authoring checks: what the file says against what it means (docs/linkage-files.md, "Authoring
// checks"). A description can be valid and still not be the mechanism its author drew: a length
// that disagrees with the rough positions, a body written mirrored, an angle in radians. The reader
// cannot see these; they show when the rough positions are compared with the lengths, the shapes
// and the driver, and with the reference pose solved from them.
//
//   error    the crank's `angle` (or a slider's `angle`) disagrees with the rough positions by more
//            than driver_angle_tolerance_deg: the branch would be picked from a wrong start
//   warning  a joint solved far from its rough position (more than joint_shift_fraction of its
//            shortest link), a link whose rough positions disagree with its length (relative
//            difference over link_length_tolerance), a body whose local coordinates are the
//            mirror image of its rough positions
//
// Every tolerance is relative (to a length, an area or an angle), so a file scaled by any factor
// gets the same verdicts.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms {

class LinkageModel;

inline constexpr double driver_angle_tolerance_deg = 5.0;
inline constexpr double joint_shift_fraction = 0.1;
inline constexpr double link_length_tolerance = 0.05;

// One warning: where in the file, and what (one line, without the file name).
struct AuthoringWarning {
  SourcePlace place;
  std::string text;
};

// "FILE:LINE: text", the form numlab prints after "numlab: warning: ".
std::string warning_line(const std::string& file, const AuthoringWarning& warning);

// Throws LinkageFileError, at the angle's place, when the crank's angle disagrees with the rough
// positions of its pivot and joint, or a slider's angle with the line from its `through` point to
// its joint's rough position; the message suggests degrees when the value reads as radians.
void check_driver_angles(const LinkageDescription& description);

// The warnings of a model whose reference pose (model unknowns) solved from the rough positions is
// `reference`, in file order.
std::vector<AuthoringWarning> authoring_warnings(const LinkageModel& model, const Eigen::VectorXd& reference);

// The reference pose solved again to a tolerance relative to the mechanism's size (damped Newton
// from `start`, or from the rough positions when `start` is empty): the solver's own tolerance is
// absolute, and a millimetre-sized file would otherwise stop at its rough positions.
Eigen::VectorXd polished_reference(const LinkageModel& model, const Eigen::VectorXd& start);

// Which way a body turns: the signed areas of its spanning triangle (its two local points farthest
// apart and the one farthest from their line) in its local coordinates and at `positions` (one per
// joint of the description). A body placed at its own distances is its mirror image exactly when
// the two signs differ (the mirrored-body warning, and a redundant body held mirrored by the others).
struct BodyTurn {
  std::array<int, 3> joints{};       // the triangle's joints, indices into the description's joints
  double local = 0.0, placed = 0.0;  // signed areas
  // The triangle at `positions` turns the other way, with at least `fraction` of its local area.
  bool mirrored(double fraction) const;
  // "A, B, C turn clockwise in 'local', counter-clockwise in WHERE".
  std::string text(const LinkageDescription& description, const std::string& where) const;
};
BodyTurn body_turn(const BodySpec& body, const std::vector<Eigen::Vector2d>& positions);

// The mechanism's size: the largest link length, body extent or distance between two joints' rough
// positions.
double mechanism_size(const LinkageDescription& description);

}  // namespace numlab::mechanisms
