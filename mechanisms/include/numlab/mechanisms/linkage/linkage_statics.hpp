#pragma once
// The driving torque: the driver torque (crank) or force (slider) that holds a linkage in
// quasi-static equilibrium under the file's [[load]]s, and the reactions of its supports
// (docs/linkage-files.md, "Loads and the driving torque").
//
// Lagrange multipliers, with the Jacobian J = d Phi / d q the sweep already has (square: its rows
// include the driver's):
//
//   1. Q: the loads as forces on the moving joints (a torque T on a link or body as a couple:
//      T perp(d) / |d|^2 at its second joint, minus that at its first, d from first to second;
//      a mass m as (0, -m g)).
//   2. Solve J^T lambda = Q: the constraint forces -J^T lambda balance the loads at every joint.
//   3. The driver's load is lambda . Phi_t (Phi_t = d Phi / d t): by virtual work, with J v = -Phi_t,
//      lambda . Phi_t = -(J^T lambda) . v = -Q . v, so driver * 1 + sum F . v_J = 0 per radian (or
//      per unit of travel). A crank's is the torque it applies, counter-clockwise positive; a slider
//      driver's the force along its line's direction.
//   4. The reactions, from the same lambda: at a ground joint g the force the ground exerts on the
//      mechanism, sum_r lambda_r d Phi_r / d p_g minus the loads applied at g; at a slider's joint the
//      force its guide exerts, -lambda d(u x (p - P)) / d p (normal to the guide).
//
// Units: forces in N, lengths in the file's unit, torques in N times that unit (N mm for a file in
// mm); a mass in kg weighs m g N with g in m/s^2 whatever the length unit.
//
// Where J is singular (kappa(J) above 1e5, the sweep's threshold, or kinematics by differences) no
// finite driver load holds a general load: the status is `singular` and the numbers are +inf (null
// in JSON); never a NaN as a number.

#include <Eigen/Core>
#include <Eigen/LU>
#include <string>
#include <string_view>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms {

// A support: a ground joint, or a slider's joint on a fixed line (its guide). A slider in a moving
// link's slot, an actuator and a motor act between members: their forces are internal, and the
// driver's multiplier gives an actuator's force (N, positive pushing its joints apart) or a motor's
// torque (N x length unit, counter-clockwise positive on the link of its `joint`).
struct StaticsSupport {
  std::string name;  // the joint's name: columns reaction_<name>_x, reaction_<name>_y
  int joint = -1;
  int slider = -1;   // index into description.sliders, or -1 for a ground joint
};
// The ground joints in file order, then the joints of the sliders on fixed lines in file order.
std::vector<StaticsSupport> statics_supports(const LinkageDescription& description);

enum class StaticsStatus { equilibrium, singular, no_pose };
std::string_view to_string(StaticsStatus status);

struct LinkageStatics {
  StaticsStatus status = StaticsStatus::no_pose;
  double driver = 0.0;                      // crank, motor: torque (CCW +); slider: force along the line;
                                            // actuator: force (+ pushing apart)
  double second_driver = 0.0;               // a second driver's load (lambda . d Phi / d s), the same
                                            // units and signs; 0 when there is none
  std::vector<Eigen::Vector2d> reactions;   // one per statics_supports() entry
};

// Every joint's applied load as a force (ground joints too), at positions from q: the loads of
// step 1. `forces` must hold one entry per joint.
void applied_joint_forces(const LinkageModel& model, const Eigen::VectorXd& q, std::vector<Eigen::Vector2d>& forces);

// Steps 1-4 at a pose. Everything is allocated in the constructor: solve() allocates nothing.
class LinkageStaticsSolver {
 public:
  explicit LinkageStaticsSolver(const LinkageModel& model);
  explicit LinkageStaticsSolver(const LinkageModel&&) = delete;  // it keeps a reference to the model

  // The pose's statics: no_pose when it did not converge; singular when J is (see above).
  const LinkageStatics& solve(const LinkagePose& pose);
  const LinkageStatics& result() const { return result_; }
  const Eigen::VectorXd& multipliers() const { return lambda_; }  // lambda of the last equilibrium

 private:
  const LinkageModel& model_;
  std::vector<StaticsSupport> supports_;
  std::vector<int> guide_rows_;  // per support: the slider_line row of a slider support, else -1
  std::vector<Eigen::Vector2d> guide_normals_;  // per support: that row's gradient, perp(u)
  Eigen::MatrixXd J_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd Q_, lambda_, phi_t_;
  std::vector<Eigen::Vector2d> applied_, constraint_;
  LinkageStatics result_;
};

}  // namespace numlab::mechanisms
