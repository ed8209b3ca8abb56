#pragma once
// The Mustang linkage over a range of input angles, by continuation from seed 003's branch, and
// the assembly limits where it stops.
//
//  1. Start at theta = 45 deg from seed 003's guess (mustang_seed_start).
//  2. March up through the requested angles above 45 deg and down through those below, each
//     solve starting from a prediction (the last two poses extrapolated). An angle is marched to
//     at its equal whole turns away that is nearest 45 deg (crank_angle.hpp); the pose keeps the
//     requested angle. The walk to a direction's first angle takes steps of up to 1 deg; from one
//     requested angle to the next no step is larger than the requested step or 1 deg.
//  3. A step fails when the solver does not converge or the pose left the branch (a dyad flipped
//     to its other side, or loop 4's kite folded). A failed step is retried from the last pose, then halved.
//  4. Halving near a limit is a bisection on theta: it stops when the step is below the
//     resolution (0.01 deg). If the linkage cannot close `resolution` beyond the last pose that
//     assembled (the dyad's circles no longer meet), that is the assembly limit, and the loop is
//     named; otherwise the solver failed where the linkage does close, reported with its status.

#include <vector>

#include "numlab/mechanisms/mustang_solvers.hpp"
#include "numlab/mechanisms/sweep_observer.hpp"

namespace numlab::mechanisms {

struct MustangPose {
  double crank_deg = 0.0;
  MustangAngles angles;
  MustangJoints joints;
  PoseOutcome outcome;
  double condition = 0.0;             // kappa_2 of the 8x8 Jacobian at the pose
  double closed_form_distance = 0.0;  // max over joints of |joint - closed-form joint|
  double closed_form_bound = 0.0;     // the distance its residual and conditioning justify (closed_form_bound.hpp)
  double length_error = 0.0;          // worst link-length error
  double rigid_error = 0.0;           // worst rigid-body shape error
  double fixed_error = 0.0;           // worst fixed-point error
};

struct MustangLimit {
  bool reached = false;
  Status status = Status::converged;  // cannot_assemble, or the solver's own failure
  double last_assembled_deg = 0.0;    // the last angle solved in this direction
  double failed_deg = 0.0;            // the nearest angle beyond it that failed
  int loop = 0;                       // 1 ... 4: the loop whose dyad cannot close there
  int solver_loop = 0;                // the loop the solver itself failed in (sequential), or 0
};

struct MustangSweep {
  std::vector<MustangPose> poses;  // the requested angles that assembled, in the requested order
  Status status = Status::running;  // converged, a limit's status, or no_progress when a pose is not verified
  MustangLimit lower, upper;       // towards smaller and larger theta (limits' angles within half a turn of 45)
  int step_halvings = 0;
  bool branch_kept = true;         // every pose verified: within its bound of the closed form on the seed's
                                   // branch, the bound below half the shortest link (closed_form_bound.hpp)
  double worst_angle_rate = 0.0;   // max over neighbours of ||dx||_inf / |d theta| (continuity)
  double worst_closed_form_distance = 0.0, worst_length_error = 0.0, worst_rigid_error = 0.0, worst_fixed_error = 0.0;
  double worst_closed_form_bound = 0.0;
};

struct MustangSweepOptions {
  double resolution_deg = 0.01;  // how closely a limit is located
  double max_step_deg = 1.0;     // no continuation step is larger
  bool checks = true;            // closed form, lengths, rigid bodies, condition (off for timing)
};

// The sweep as a stepper (numlab/solver.hpp): the first step is the seed's start (1), then each
// step reaches one requested angle (2-4), upwards first, then downwards; a limit ends a direction.
// The observer sees every solve attempted (as the trace), except the refinement of a requested
// angle the sweep already stands on.
class MustangSweepStepper {
 public:
  explicit MustangSweepStepper(MustangPoseSolver& solver, const MustangSweepOptions& options = {})
      : solver_(solver), options_(options) {}
  void set_observer(SweepObserver<MustangSweepStepper>* observer) { observer_ = observer; }

  // Throws std::invalid_argument for a step of zero, one that points away from stop, or more than
  // max_sweep_poses poses (crank_angle.hpp).
  void start(double start_deg, double stop_deg, double step_deg);
  bool step();
  MustangSweep solve(double start_deg, double stop_deg, double step_deg);

  bool running() const { return status_ == Status::running && !stopped_; }
  Status status() const { return status_; }
  bool stopped() const { return stopped_; }
  int iterations() const { return poses_; }              // poses solved so far (the seed's start included)
  const MustangAngles& x() const { return x_; }          // the last pose solved
  double crank_deg() const { return deg_; }              // ... and its crank angle
  const MustangSweep& result() const { return sweep_; }

 private:
  bool start_from_seed();
  bool reach_next_target();
  void begin_direction(int direction);
  bool finish();
  bool advance_to(double target_deg, PoseOutcome& last, MustangLimit& limit);
  bool try_solve(double next, bool predict, MustangAngles& trial, PoseOutcome& outcome);
  MustangLimit diagnose(double failed_deg, const PoseOutcome& outcome) const;

  MustangPoseSolver& solver_;
  MustangSweepOptions options_;   // as given
  MustangSweepOptions marching_;  // with max_step_deg no larger than the requested step
  SweepObserver<MustangSweepStepper>* observer_ = nullptr;
  MustangLinkage linkage_;
  MustangSweep sweep_;
  std::vector<MustangPose> poses_found_;
  struct Target {
    double requested;  // the angle asked for
    double at;         // the same angle whole turns away, nearest 45 deg: where the sweep solves it
  };
  std::vector<Target> up_, down_;  // the requested angles above and below the start, in marching order
  double step_deg_ = 0.0;
  bool seeded_ = false;
  Status status_ = Status::running;  // no verdict before the sweep has finished
  bool stop_requested_ = false;      // the observer said stop during this step
  bool stopped_ = false;
  int poses_ = 0;
  std::size_t next_target_ = 0;
  // The march in the current direction: the last pose, the one before it, and the step between.
  MustangAngles start_x_ = MustangAngles::Zero(), x_ = MustangAngles::Zero(), previous_ = MustangAngles::Zero();
  double deg_ = 0.0, previous_step_ = 0.0;
  bool has_previous_ = false;
  int direction_ = +1;
};

// MustangSweepStepper(...).solve(): solves start, start + step, ... up to stop (degrees).
MustangSweep mustang_sweep(MustangPoseSolver& solver, double start_deg, double stop_deg, double step_deg,
                           const MustangSweepOptions& options = {},
                           SweepObserver<MustangSweepStepper>* observer = nullptr);

// The smallest loop's distance from its limit at (theta, x) (0 where a dyad's circles just touch).
double mustang_smallest_margin(double theta, const MustangAngles& x);

}  // namespace numlab::mechanisms
