#pragma once
// The Ford Mustang roof linkage of seed 003: joints P0 ... P12 from the angles, the closed-form
// (circle-intersection) solution on the seed's branch, and the checks every pose must pass.
// The model's assumptions are listed in mustang_closure.hpp; two more are here:
//  - Major link 9-11-12 is rigid and turns 40 degrees at 11 (11->12 at u(pi - H - 40 deg)), as
//    link 2-4-6 turns at 4. Seed 003 put 12 at 2.506 = 2 (4/3) cos 20 along u(pi - H - 20 deg) from
//    9, a chord that needs |9 11| = |11 12| = 4/3; with the given |9 11| = 1 and |11 12| = 4/3 it
//    breaks the triangle inequality (2.506 > 1 + 4/3). Here |9 12| = 2.196.
//  - Loop 4 (8-10-11-9) is a kite (|8 9| = |9 11| = 1, |8 10| = |10 11| = 4/3): it always closes,
//    in two ways, P11 = P8 (folded) or P11 = P8 mirrored in the line 9-10 (open). The seed's
//    branch is the open one. The two meet where 8, 9, 10 are collinear (near theta = 43.15 deg on
//    this branch), where loop 4's Jacobian is singular.

#include <Eigen/Core>
#include <array>
#include <string_view>

#include "numlab/mechanisms/mustang_closure.hpp"

namespace numlab::mechanisms {

inline constexpr int mustang_joint_count = 13;
inline constexpr std::array<std::string_view, 13> mustang_joint_names = {"P0", "P1", "P2",  "P3",  "P4",  "P5", "P6",
                                                                         "P7", "P8", "P9", "P10", "P11", "P12"};
inline constexpr std::array<std::string_view, 8> mustang_angle_names = {"A", "B", "C", "D", "E", "F", "G", "H"};
// The quadrilateral each loop closes, for messages.
inline constexpr std::array<std::string_view, 4> mustang_loop_names = {
    "loop 1 (A, B: quadrilateral 1-2-4-3)", "loop 2 (C, D: quadrilateral 0-2-6-5)",
    "loop 3 (E, F: quadrilateral 6-7-10-8)", "loop 4 (G, H: quadrilateral 8-10-11-9)"};

using MustangJoints = std::array<Eigen::Vector2d, 13>;  // P0 ... P12
using MustangAngles = MustangClosure::Vector;           // A ... H

// A link, or a side of a rigid body: two joints and the distance between them.
struct MustangLink {
  int from, to;
  double length;
};

struct MustangClosedForm {
  Status status = Status::converged;  // or cannot_assemble
  int failed_loop = 0;                // 1 ... 4 when a loop cannot close, else 0
  MustangJoints joints{};             // valid when converged
};

class MustangLinkage {
 public:
  explicit MustangLinkage(MustangLengths lengths = {});

  // Joint positions from theta and A ... H, each joint from the chain of links that defines it.
  MustangJoints joints(double theta, const MustangAngles& x) const;

  // The closed form on the seed's branch: P3, P5, P10 by circle intersections on the sides
  // below, P11 as P8 mirrored in the line 9-10. Names the first loop that cannot close.
  MustangClosedForm closed_form(double theta) const;
  // The angles of given joints, each within pi of `near`.
  static MustangAngles angles_of(const MustangJoints& joints, const MustangAngles& near);

  // How far loop k's dyad is from its limit (0 at the limit, negative past it): for circles of
  // radii r1, r2 whose centres are d apart, min(d - |r1 - r2|, r1 + r2 - d).
  double loop_margin(int k, const MustangJoints& joints) const;

  // Every fixed distance: the 16 links and each rigid body's other sides.
  const std::vector<MustangLink>& links() const { return links_; }
  // max over links of | |P_to - P_from| - length |.
  double worst_length_error(const MustangJoints& joints) const;
  // max over rigid bodies of how far their shape is from the reference one, mirror images
  // included: every pair's distance and every triple's signed area (so a flipped body fails).
  double worst_rigid_body_error(const MustangJoints& joints) const;
  // max distance of P0, P1, P2 from where they are fixed.
  static double worst_fixed_point_error(const MustangJoints& joints);

  const MustangLengths& lengths() const { return lengths_; }

  // Whether a pose is on the seed's branch: P3, P5, P10 on the sides below, and loop 4 open
  // (P11 nearer to P8 mirrored in the line 9-10 than to P8 itself). A geometric test, so it
  // holds through loop 4's crossing, where the folded and the open kite meet.
  static bool on_seed_branch(const MustangJoints& joints);

  // The sides of the seed's branch (verified against Newton from the seed's start by a test):
  // P3 relative to the line P1 -> P4, P5 to P0 -> P6, P10 to P8 -> P7 (+1 left, -1 right).
  static constexpr int side_P3 = -1, side_P5 = -1, side_P10 = 1;

 private:
  MustangLengths lengths_;
  std::vector<MustangLink> links_;
  std::vector<std::vector<int>> bodies_;  // joints of each rigid body
  std::vector<MustangJoints> reference_;  // a pose each body's shape is read from
};

}  // namespace numlab::mechanisms
