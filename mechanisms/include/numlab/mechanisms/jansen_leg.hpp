#pragma once
// The Jansen leg of seed 000: joints, the closed-form (circle-intersection) solution, and the
// checks every pose must pass. Frame, names and lengths: docs/mechanisms.md.
//
// Joints: O (crank pivot, origin), P1 = (-b, -a) (fixed), A (crank tip), B, C, D, E, F (foot).
// Angles theta1 ... theta8 (radians from +x) are the directions A->B, P1->B, B->C, P1->C, C->E,
// A->D, P1->D, D->E; F = D + l9 u(theta8 + c) on the rigid triangle D-E-F (seed 000 eqs 15-21).

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string_view>

#include "numlab/mechanisms/jansen_closure.hpp"

namespace numlab::mechanisms {

enum class JansenJoint { O, P1, A, B, C, D, E, F };
inline constexpr int jansen_joint_count = 8;
inline constexpr std::array<std::string_view, 8> jansen_joint_names = {"O", "P1", "A", "B", "C", "D", "E", "F"};

using JansenJoints = std::array<Eigen::Vector2d, 8>;  // indexed by JansenJoint: joints[at(JansenJoint::A)]
inline constexpr std::size_t at(JansenJoint joint) { return static_cast<std::size_t>(joint); }
using JansenAngles = JansenClosure::Vector;           // theta1 ... theta8

// A link (or a rigid body's edge): two joints and the distance between them.
struct JansenLink {
  JansenJoint from, to;
  double length;
};

// Rates per unit crank rate (d/d theta_i; multiply by the crank's angular speed for time rates).
struct JansenRates {
  JansenAngles angle_rates;       // d theta_k / d theta_i, k = 1..8
  Eigen::Vector2d foot_velocity;  // dF / d theta_i
  double foot_speed;              // |dF / d theta_i|: length units per radian of crank
  Status status;                  // singular if J could not be solved (a toggle position)
};

class JansenLeg {
 public:
  explicit JansenLeg(JansenLengths lengths = {}, JansenFootLengths foot = {});

  // Joint positions from the crank angle and theta1 ... theta8 (seed 000 eqs 15-20).
  JansenJoints joints(double crank_angle, const JansenAngles& theta) const;

  // The closed-form solution on the seed's branch: circle intersections A -> B -> C, A -> D,
  // C & D -> E, then F. Nothing if some dyad cannot close (the Jansen leg always can).
  std::optional<JansenJoints> closed_form_joints(double crank_angle) const;
  // The angles of those joints, each within pi of `near` (so they follow a sweep continuously).
  static JansenAngles angles_of(const JansenJoints& joints, const JansenAngles& near);

  // Angular rates and the foot's velocity at a solved pose: differentiating f(theta; theta_i) = 0
  // gives J d(theta)/d(theta_i) = -df/d(theta_i), one more solve with the Jacobian at hand.
  JansenRates rates(double crank_angle, const JansenAngles& theta) const;

  // The eleven fixed distances: nine links plus the two rigid triangles' third sides (P1-C, E-F).
  const std::array<JansenLink, 11>& links() const { return links_; }
  // max over links of | |joint_to - joint_from| - length |.
  double worst_length_error(const JansenJoints& joints) const;
  // +1 or -1: the orientation of the rigid triangles P1-B-C and D-E-F (must not flip in a sweep).
  static int triangle_orientation(const JansenJoints& joints);

  const JansenLengths& lengths() const { return lengths_; }
  double foot_angle() const { return foot_angle_; }  // c, the interior angle at D (seed 000 eq 21)

  // Which side of each dyad the seed's branch takes (verified against Newton from seed 000's
  // estimates by a test): B, C, D, E relative to their circle centres in the order used above.
  static constexpr int side_B = -1, side_C = -1, side_D = 1, side_E = -1;

 private:
  JansenLengths lengths_;
  JansenFootLengths foot_;
  double foot_angle_;
  std::array<JansenLink, 11> links_;
};

}  // namespace numlab::mechanisms
