#pragma once
// Ways to find one pose of the Jansen leg, behind one interface, and the crank sweep over them.
//
// Solver names (docs/cli.md): full (hand-written Newton, inner solver from `linear`: gepp,
// gauss-seidel, gsl-lu, eigen-lu), sequential (block by block: seed 000's four 2x2 blocks with the
// closed-form inverse; seed 001's five, found from the pattern), analytic (circle intersections),
// gsl-<type> (GSL's multiroot types).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/pose_solver.hpp"
#include "numlab/mechanisms/sweep_observer.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

enum class JansenModel { eight_equations, ten_equations };  // seed 000, seed 001

// The Jansen leg's pose solvers work on a dynamic vector: 8 or 10 angles, by model.
using JansenPoseSolver = PoseSolver<Eigen::VectorXd>;

// The unknowns' names: theta1 ... theta8, or theta3 ... theta12.
std::vector<std::string> jansen_angle_names(JansenModel model);

// Joints of either model's angles.
JansenJoints jansen_joints(JansenModel model, const JansenLeg& leg, double crank_angle, const Eigen::VectorXd& angles);

// The model's angles for given joints, each within pi of `near`.
Eigen::VectorXd jansen_angles_of(JansenModel model, const JansenJoints& joints, const Eigen::VectorXd& near);

// The start of every sweep: seed 000's estimates at theta_i = 1.57 rad (for the 10-equation
// model, the same estimates converted through the joints they describe).
Eigen::VectorXd jansen_seed_estimates(JansenModel model, const JansenLeg& leg);

const std::vector<std::string>& jansen_solver_names();

// Throws std::invalid_argument for an unknown solver or linear method.
std::unique_ptr<JansenPoseSolver> make_jansen_solver(JansenModel model, const std::string& solver,
                                                     const std::string& linear, const nonlinear::NewtonOptions& options);

struct JansenPose {
  double crank_deg = 0.0;
  Eigen::VectorXd angles;
  JansenJoints joints;
  PoseOutcome outcome;
  double closed_form_distance = 0.0;  // max over joints of |joint - closed-form joint|
  double closed_form_bound = 0.0;     // the distance its residual and conditioning justify (closed_form_bound.hpp)
  double length_error = 0.0;          // worst link-length error
};

struct JansenSweep {
  std::vector<JansenPose> poses;  // the requested angles that were solved, in order
  Status status = Status::running;  // converged; no_progress when every pose converged but one is not verified
  int step_halvings = 0;           // how often a failed step was halved
  int walk_in_poses = 0;           // poses solved to walk from 1.57 rad to the first angle
  double worst_closed_form_distance = 0.0;
  double worst_closed_form_bound = 0.0;
  double worst_length_error = 0.0;
  bool closed_form_verified = true;  // every pose within its bound of the closed form, the bound below
                                     // half the crank (closed_form_bound.hpp)
  bool orientation_kept = true;    // the branch kept: the rigid triangles never flipped, and closed_form_verified
};

// The solved angles of a sweep and nothing derived from them: what `numlab bench jansen` times.
struct JansenSweepAngles {
  Eigen::MatrixXd angles;           // column i: the angles of pose i (only the first outcomes.size() are solved)
  std::vector<double> crank_deg;    // the crank angle of each solved pose
  std::vector<PoseOutcome> outcomes;
  Status status = Status::running;  // until the sweep has ended
  int step_halvings = 0;
  int walk_in_poses = 0;
};

struct JansenSweepOptions {
  int max_halvings = 20;  // a failed step is halved at most this often (in all) before the sweep stops
  bool checks = true;     // crank_sweep(): joints, lengths and orientation checked against the closed form
};

// The crank sweep as a stepper (numlab/solver.hpp). Solves start, start + step, ... up to stop
// (degrees), each pose starting from a prediction extrapolated from the poses before.
//
//  1. Solve at 1.57 rad from seed 000's estimates (the first step).
//  2. If `start` is elsewhere, walk there in steps of walk_in_step_deg (a step each), whatever the
//     sweep's own step; to the angle a whole number of turns from `start` that is nearest 1.57 rad
//     (at most 180 deg away: crank_angle.hpp), since it has the same pose.
//  3. Solve each requested angle from the polynomial through the last poses (a step each).
//  4. A failed solve is retried with the step halved, from the prediction and then from the last
//     pose, up to options.max_halvings times; then the sweep stops with the solver's status.
//
// step() moves the sweep one pose on (its retries included); the observer sees every attempt.
class JansenSweepStepper {
 public:
  JansenSweepStepper(JansenModel model, JansenPoseSolver& solver, const JansenSweepOptions& options = {})
      : model_(model), solver_(solver), options_(options) {}
  void set_observer(SweepObserver<JansenSweepStepper>* observer) { observer_ = observer; }

  static constexpr double walk_in_step_deg = 5.0;  // the walk-in's own step (step 2)

  // Throws std::invalid_argument for a step of zero, one that points away from stop, or more than
  // max_sweep_poses poses (crank_angle.hpp).
  void start(double start_deg, double stop_deg, double step_deg);
  bool step();
  JansenSweepAngles solve(double start_deg, double stop_deg, double step_deg);

  bool running() const { return status_ == Status::running && !stopped_; }
  Status status() const { return status_; }
  bool stopped() const { return stopped_; }
  int iterations() const { return poses_; }                // poses solved so far (walk-in included)
  const Eigen::VectorXd& x() const { return angles_; }    // the last pose solved
  double crank_deg() const { return current_deg_; }        // ... and its crank angle
  const JansenSweepAngles& result() const { return sweep_; }

 private:
  enum class Phase { seed, walk_in, requested, finished };
  bool solve_seed_pose();
  bool walk_in_one_pose();
  bool solve_requested_pose();
  void begin_requested_poses();
  bool finish(Status status);
  PoseOutcome advance_to(double target_deg);
  PoseOutcome solve_pose(double deg, double step_deg, Eigen::VectorXd& x);
  [[gnu::noinline]] void notify(double deg, double step_deg, const PoseOutcome& outcome, const Eigen::VectorXd& x);

  JansenModel model_;
  JansenPoseSolver& solver_;
  JansenSweepOptions options_;
  SweepObserver<JansenSweepStepper>* observer_ = nullptr;
  JansenSweepAngles sweep_;
  Phase phase_ = Phase::finished;
  Status status_ = Status::running;  // no verdict before the sweep has finished
  bool stop_requested_ = false;      // the observer said stop during this step
  bool stopped_ = false;
  double start_deg_ = 0.0, step_deg_ = 0.0, current_deg_ = 0.0, walk_to_deg_ = 0.0;
  int count_ = 0, next_ = 0, poses_ = 0;
  Eigen::VectorXd angles_, trial_;  // the last pose solved; the pose being tried
};

// JansenSweepStepper(...).solve(): the solved angles and nothing derived from them, what
// `numlab bench jansen` times.
JansenSweepAngles solve_crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                                    double step_deg, const JansenSweepOptions& options = {},
                                    SweepObserver<JansenSweepStepper>* observer = nullptr);

// solve_crank_sweep(), then each pose's joints and (with options.checks) its checks against the closed form.
JansenSweep crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                        double step_deg, const JansenSweepOptions& options = {},
                        SweepObserver<JansenSweepStepper>* observer = nullptr);
// The second half of crank_sweep(): the poses a JansenSweepStepper solved, with their joints and
// (with options.checks) their checks against the closed form. For a caller that drives the stepper.
JansenSweep checked_sweep(JansenModel model, const JansenSweepAngles& solved, const JansenSweepOptions& options = {});

}  // namespace numlab::mechanisms
