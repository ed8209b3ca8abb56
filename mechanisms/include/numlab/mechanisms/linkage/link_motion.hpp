#pragma once
// Every link's angle, angular velocity and angular acceleration, and an output's velocity ratio
// (docs/linkage-files.md, "Link angles and the output").
//
// A link (or body) turns with the line from its first joint to its second, d = p_to - p_from:
//   theta  = atan2(d_y, d_x)
//   omega  = (d x d') / |d|^2
//   alpha  = (d x d'') / |d|^2 - 2 (d . d') omega / |d|^2
// with d' and d'' from the joints' velocities and accelerations (J q' = -Phi_t, J q'' = gamma: the
// model's own derivatives, per radian of crank). For a rigid link d . d' = 0 and alpha is the
// familiar (d x d'') / |d|^2; the full quotient rule is kept so that the formula reads as a
// derivative of atan2 and holds for any pair of points.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::mechanisms {

// A link's name: its `name`, else its joints joined by '-' ("O-A").
std::string link_name(const LinkageDescription& description, const LinkSpec& link);
// A body's name for the columns: its `name`, else its joints joined by '-' (the default "body K"
// of the messages has a space, which a column name cannot).
std::string body_column_name(const BodySpec& body, const LinkageDescription& description);

// Each [[link]], then each [[body]], in file order: its name and the two joints whose line it turns with.
struct LinkLine {
  std::string name;
  int from = -1, to = -1;  // joint indices
  bool body = false;
  SourcePlace place;       // the item's (or its `name`'s) place in the file
};
std::vector<LinkLine> link_lines(const LinkageDescription& description);

// One joint's position, velocity and acceleration (ground joints: fixed, zero).
struct JointMotion {
  Eigen::Vector2d p, v, a;
};

// Every joint's motion at a pose from the unknowns q, q' and q'' (empty q' or q'': NaN).
std::vector<JointMotion> joint_motions(const LinkageModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& velocity,
                                       const Eigen::VectorXd& acceleration);

// theta (radians, atan2's range), omega and alpha of the line from `from` to `to`.
struct AngularMotion {
  double angle = 0.0, omega = 0.0, alpha = 0.0;
};
AngularMotion angular_motion(const JointMotion& from, const JointMotion& to);

// What --output or `output = "..."` names: a link or body (its angle), or a slider's joint (its travel
// along the slider's line; for a slider on a moving link, s = (p_A - p_B) . w along its line B -> C,
// w = (p_C - p_B) / |p_C - p_B|).
struct LinkageOutput {
  std::string name;
  int line = -1;                              // index into link_lines(), or -1
  int slider = -1;                            // index into description.sliders, or -1
  int joint = -1;                             // the slider's joint, or -1
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // a slider's unit direction
  int line_from = -1, line_to = -1;           // a slider on a moving link: its line's joints B, C
  bool angle() const { return line >= 0; }
};
// The output called `name`, or nullopt.
std::optional<LinkageOutput> find_output(const LinkageDescription& description, std::string_view name);
// "links O-A, A-B, Q-B; bodies coupler; slider joints S": what an output may name, for messages.
std::string output_choices(const LinkageDescription& description);

// The output's rate per unit of driver: omega of its line, u . v of its slider joint, or for a slider
// on a moving link s' = (v_A - v_B) . w + (p_A - p_B) . w', w' = (d' - w (w . d')) / |d|, d = p_C - p_B.
double output_rate(const LinkageOutput& output, const std::vector<LinkLine>& lines, const std::vector<JointMotion>& joints);

// The mechanical advantage of an ideal (lossless) mechanism is the inverse of the velocity ratio:
// infinite where the output stands still (a toggle), NaN where the ratio is NaN. Never a NaN for an
// infinity: 1 / 0 is +inf whatever the zero's sign.
double mechanical_advantage(double velocity_ratio);

}  // namespace numlab::mechanisms
