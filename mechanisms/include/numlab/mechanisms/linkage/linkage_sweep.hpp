#pragma once
// A linkage over a driver sweep: every pose solved from the one before (continuation from the
// reference pose), with per pose the joints, their velocities and accelerations, kappa(J), the
// branch signature and every dyad's transmission angle; where the linkage stops assembling, the
// limit found by bisection and the block that cannot close.
//
// Velocity and acceleration come from the Jacobian already at hand (per radian of crank, or per
// unit of slider travel):
//   J qdot  = -Phi_t
//   J qddot = gamma = -(qdot' Phi_qq qdot + Phi_tt)
// check_derivatives() compares them with finite differences of solved positions.

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/solver.hpp"

namespace numlab::mechanisms {

struct LinkagePose {
  double driver = 0.0;                // user units: degrees of crank, or slider travel
  double second_driver = std::numeric_limits<double>::quiet_NaN();  // a driver path's second driver (user
                                      // units); NaN in a sweep, which holds it at LinkageModel::second_driver()
  Eigen::VectorXd q;                  // the unknowns (moving joints' x, y)
  Eigen::VectorXd velocity;           // dq/dt; empty when the pose did not converge
  Eigen::VectorXd acceleration;       // d2q/dt2
  nonlinear::NewtonCounts outcome;
  int failed_block = -1;              // the block that failed (sequential and analytic)
  double condition = 0.0;             // kappa_2(J) (NaN when not converged)
  double closed_form_distance = 0.0;  // max |q - closed form| when every block has one (NaN otherwise)
  double closed_form_bound = 0.0;     // how far the residual test allows: 10 ||J^-1||_2 (||Phi||_2 + n eps |q|)
  std::vector<int> signature;         // per block (LinkageSolver::signature)
  std::vector<double> transmission_deg;  // per block, NaN for non-dyads
  int step_halvings = 0;              // continuation steps halved to reach this pose
  bool kinematics_by_differences = false;  // J singular here (a crossing): velocity and acceleration are
                                           // the 7-point stencils of positions solved along the branch
  bool branch_kept = false;           // converged, and no jump to another branch up to here
  bool jumped = false;                // solved, but further from its prediction than allowed even at the
                                      // shortest sub-step: on another branch (status no_progress)
  double not_tried_past = std::numeric_limits<double>::quiet_NaN();  // not solved: the continuation
                                      // from the last good pose already failed at this driver value (user
                                      // units), short of this pose; the failure is reported again, with no work
};

// Where the linkage stops assembling between two poses of the sweep.
struct LinkageLimit {
  double driver = 0.0;            // the last assembling value found by bisection (user units)
  double bracket = 0.0;           // the width of the final bracket (user units), <= 0.01 deg
  int block = -1;                 // the block that cannot close beyond it
  double transmission_deg = 0.0;  // that block's transmission angle at the limit (NaN: not a dyad)
  bool upper = true;              // the sweep leaves the assembling range (true) or enters it
  bool assembles_beyond = false;  // the closed form (or the sequential solver) assembles just past it:
                                  // the solver failed there, not the mechanism (no fold)
};

// Where two assembly branches cross: a dyad's two solutions meet (J is singular) and part again. On
// the smooth branch (the one whose positions go on smoothly through the crossing) the dyad's side
// changes; on the other it stays.
struct LinkageCrossing {
  double driver = 0.0;       // user units, where the dyad's margin reaches zero
  int block = -1;
  int side_before = 0;       // the block's signature before and after (LinkageSolver::signature)
  int side_after = 0;
  bool switched = false;     // the sweep went on along the other branch (AtCrossing::switch_branch)
  bool tangency = false;     // the solutions met and parted on the same side: a tangency, not a crossing
};

// Which branch a sweep follows past a crossing: the smooth one (default), or the other.
enum class AtCrossing { smooth, switch_branch };

struct LinkageSweep {
  std::vector<LinkagePose> poses;
  Status status = Status::running;    // converged when every pose did; else the first failure's
  bool branch_kept = true;            // no block's signature changed between poses but at change points
  bool closed_form_verified = true;   // every converged pose within its closed-form bound, and that bound
                                      // below half the shortest length (when there is a closed form)
  std::vector<std::string> flips;     // a block that jumped to another branch between two poses
  std::vector<std::string> change_points;  // each crossing and tangency in words (reported, not a flip)
  std::vector<LinkageCrossing> crossings;
  std::vector<std::string> jumps;          // a pose that left its branch: further from the prediction than allowed
  std::vector<LinkageLimit> limits;
  bool stopped = false;  // the observer ended the sweep early
};

struct LinkageSweepOptions {
  int max_halvings = 8;  // a continuation sub-step is halved at most this often (0 ... 60)
};

// The sweep as a stepper (numlab/solver.hpp): the poses start, start+step, ..., stop (user units).
// Each pose is predicted by the quadratic through the last solved poses (sub-steps of at most 2
// degrees), which carries the sweep along the smooth branch through a crossing; at_crossing =
// switch_branch takes the other branch there.
//
//  1. start(): walk from the reference pose to the start (the shorter way round for a crank).
//  2. step(): the next requested pose from the one before, through sub-steps each from the
//     predictor; a failed pose is retried from the last good one by halving;
//  3. a change between assembling and not is a limit, bracketed by bisection;
//  4. a converged pose's branch is watched (crossings, tangencies, jumps) and its closed form checked.
//
// The observer sees each pose as soon as it is made; StepControl::stop ends the sweep there (the
// poses so far, stopped(), result().stopped, status running: no verdict). Without an observer at
// start() the poses are solved on the fast path (linkage_fast_solver.hpp) where it applies; with
// one (--trace, --step) by the generic solver: the same poses, checked by tests/mechanisms/linkage/fast/.
class LinkageSweepStepper {
 public:
  explicit LinkageSweepStepper(const LinkageSolver& solver, AtCrossing at_crossing = AtCrossing::smooth,
                               const LinkageSweepOptions& options = {});
  explicit LinkageSweepStepper(const LinkageSolver&&, AtCrossing = AtCrossing::smooth,
                               const LinkageSweepOptions& = {}) = delete;  // it keeps a reference to the solver
  LinkageSweepStepper(const LinkageSweepStepper&) = delete;
  LinkageSweepStepper& operator=(const LinkageSweepStepper&) = delete;
  ~LinkageSweepStepper();
  void set_observer(StepObserver<LinkageSweepStepper, LinkagePose>* observer) { observer_ = observer; }

  // Throws std::invalid_argument for a step that is zero or not finite or points away from stop
  // (or max_halvings outside 0 ... 60).
  void start(double start, double stop, double step);
  bool step();
  LinkageSweep solve(double start, double stop, double step);  // the sweep, moved out of result()

  bool running() const { return active_; }  // from start() until the last pose (or a stop)
  Status status() const { return status_; }  // running until the last pose; then result().status
  bool stopped() const { return stopped_; }
  int iterations() const { return poses_; }  // requested poses made so far (the walk not counted)
  const Eigen::VectorXd& x() const { return x_; }  // the last pose's q (after start(): the walk's)
  const LinkageSweep& result() const { return sweep_; }

 private:
  struct State;  // the continuation between poses (linkage_sweep.cpp)
  const LinkageSolver& solver_;
  AtCrossing at_crossing_;
  LinkageSweepOptions options_;
  StepObserver<LinkageSweepStepper, LinkagePose>* observer_ = nullptr;
  std::unique_ptr<State> state_;
  LinkageSweep sweep_;
  Status status_ = Status::running;  // no verdict before the last pose
  bool active_ = false, stopped_ = false;
  double start_ = 0.0, step_ = 0.0;
  std::size_t count_ = 0, next_ = 0;
  int poses_ = 0;
  Eigen::VectorXd x_;
};

// Called with each pose as soon as it is made (for --trace and --step). StepControl::stop ends the
// sweep there: the poses so far, stopped = true and status running (no verdict).
using LinkagePoseObserver = std::function<StepControl(const LinkagePose&)>;

// LinkageSweepStepper(solver, at_crossing).solve(start, stop, step), the observer (if any) attached
// through an adapter: the fast path without one, as the stepper's.
LinkageSweep linkage_sweep(const LinkageSolver& solver, double start, double stop, double step,
                           const LinkagePoseObserver& observer = {}, AtCrossing at_crossing = AtCrossing::smooth);

// Positions only, for timing: from the reference pose to start, then every pose predicted as
// solve_crank_sweep predicts the hand-coded models' (the polynomial through the last five poses,
// extrapolated; continuation from the last pose if that fails), solved, its unknowns stored; none
// of the sweep's per-pose analysis. On the fast path (linkage_fast_solver.hpp) where it applies.
// What `numlab bench jansen` times for a description file, as it times solve_crank_sweep for the
// hand-coded models.
struct LinkageCycle {
  Eigen::MatrixXd q;  // one column per pose, allocated once
  int iterations = 0;
  Status status = Status::running;    // converged when every pose did; else the first failure's
};
LinkageCycle solve_linkage_cycle(const LinkageSolver& solver, double start, double stop, double step);

// The velocity alone: J qdot = -Phi_t.
Eigen::VectorXd linkage_velocity(const LinkageModel& model, double t, const Eigen::VectorXd& q);

// Velocity and acceleration at a solved pose (model units for t); beyond 100 unknowns from J's
// sparse LU (velocity and acceleration NaN where it finds J singular).
void linkage_kinematics(const LinkageModel& model, double t, const Eigen::VectorXd& q, Eigen::VectorXd& velocity,
                        Eigen::VectorXd& acceleration);

// kappa_2(J) and ||J^-1||_2 = 1 / sigma_min at a pose, up to 100 unknowns; beyond, kappa_1 estimated
// and an estimated upper bound of ||J^-1||_2 (linkage_conditioning.hpp).
struct LinkageConditioning {
  double condition = 0.0;
  double inverse_norm = 0.0;
};
LinkageConditioning linkage_conditioning(const LinkageModel& model, double t, const Eigen::VectorXd& q);
inline double linkage_condition(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  return linkage_conditioning(model, t, q).condition;
}

// The largest differences between the velocity and acceleration from the Jacobian and those from
// finite differences of positions solved at t +- k h (central, 2nd order, h = 1e-5 for the velocity;
// the 7-point stencil, 6th order, h = 0.01 and 0.005 for the acceleration, the finer one compared,
// their spread allowed). Every position, the pose's own included, is solved again from q_near by
// Newton to 64 eps |q|, outwards along the pose's branch.
struct DerivativeCheck {
  double velocity_difference = 0.0;
  double acceleration_difference = 0.0;
  double velocity_scale = 0.0;       // max |qdot|, for a relative reading
  double acceleration_scale = 0.0;   // max |qddot|
  double velocity_reference = 1.0;   // the mechanism's size in the velocity's units (a crank's: its longest link)
  double acceleration_reference = 1.0;
  bool solved = true;                // false when a neighbouring pose did not solve
  bool singular = false;             // kappa(J) above 1e5 at the pose: its kinematics are differences already
  bool near_meeting_point = false;   // ... with a dyad at (within 1e-3 of the size of) its meeting point:
                                     // a crossing or a fold; else J is ill-conditioned but no block is singular
  double condition = 1.0;            // kappa_2(J) at the pose
  double acceleration_reference_spread = 0.0;  // |stencil(h) - stencil(h/2)|: how far the reference itself is sure
  // Relative readings, in the units' own scale: difference / (max |qdot| + the mechanism's size).
  double velocity_relative() const { return velocity_difference / (velocity_scale + velocity_reference); }
  double acceleration_relative() const { return acceleration_difference / (acceleration_scale + acceleration_reference); }
  // What the differences may be, from the conditioning: positions solved to 64 eps are kappa times
  // that from the root, and the stencils divide by h (1e5 for the velocity's) or h^2 (6.3e4 for the
  // acceleration's weights): about 1.4e-9 kappa and 9e-10 kappa; ten times that, over the
  // truncation and rounding of a regular pose (below 1e-8).
  double velocity_allowed() const { return 1e-6 + 1.4e-8 * condition; }
  // Plus the reference's own spread: where the motion turns within a stencil's width (a near-meeting
  // of a dyad's solutions) the 7-point stencils with h and h/2 disagree, and neither is a reference
  // finer than that.
  double acceleration_allowed() const {
    return 1e-5 + 9e-9 * condition + 2.0 * acceleration_reference_spread / (acceleration_scale + acceleration_reference);
  }
  bool agrees() const { return velocity_relative() <= velocity_allowed() && acceleration_relative() <= acceleration_allowed(); }
};
DerivativeCheck check_derivatives(const LinkageSolver& solver, double t, const Eigen::VectorXd& q_near);

// Positions of a pose, as joints.
inline JointPositions pose_joints(const LinkageModel& model, const LinkagePose& pose) { return model.positions(pose.q); }

}  // namespace numlab::mechanisms
