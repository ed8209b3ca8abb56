#pragma once
// The Mustang linkage over a range of input angles, by continuation from seed 003's branch, and
// the assembly limits where it stops.
//
//  1. Start at theta = 45 deg from seed 003's guess (mustang_seed_start).
//  2. March up through the requested angles above 45 deg and down through those below, each
//     solve starting from a prediction (the last two poses extrapolated). No step is larger than
//     the requested step or 1 deg.
//  3. A step fails when the solver does not converge or the pose left the branch (a dyad flipped
//     to its other side, or loop 4's kite folded). A failed step is retried from the last pose, then halved.
//  4. Halving near a limit is a bisection on theta: it stops when the step is below the
//     resolution (0.01 deg). If the linkage cannot close `resolution` beyond the last pose that
//     assembled (the dyad's circles no longer meet), that is the assembly limit, and the loop is
//     named; otherwise the solver failed where the linkage does close, reported with its status.

#include <vector>

#include "numlab/mechanisms/mustang_solvers.hpp"

namespace numlab::mechanisms {

struct MustangPose {
  double crank_deg = 0.0;
  MustangAngles angles;
  MustangJoints joints;
  MustangOutcome outcome;
  double condition = 0.0;             // kappa_2 of the 8x8 Jacobian at the pose
  double closed_form_distance = 0.0;  // max over joints of |joint - closed-form joint|
  double length_error = 0.0;          // worst link-length error
  double rigid_error = 0.0;           // worst rigid-body shape error
  double fixed_error = 0.0;           // worst fixed-point error
};

// One solve the sweep tried (the trace): where, the step, how it went.
struct MustangAttempt {
  double crank_deg, step_deg;
  MustangOutcome outcome;
  double condition;  // kappa_2 of J where the solve ended
  double margin;     // the smallest loop margin there (0 at a limit)
  bool accepted;
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
  Status status = Status::converged;
  MustangLimit lower, upper;       // towards smaller and larger theta
  int step_halvings = 0;
  bool branch_kept = true;         // every pose within 1e-6 of the closed form on the seed's branch
  double worst_angle_rate = 0.0;   // max over neighbours of ||dx||_inf / |d theta| (continuity)
  double worst_closed_form_distance = 0.0, worst_length_error = 0.0, worst_rigid_error = 0.0, worst_fixed_error = 0.0;
  std::vector<MustangAttempt> trace;  // every solve tried, when asked for
};

struct MustangSweepOptions {
  double resolution_deg = 0.01;  // how closely a limit is located
  double max_step_deg = 1.0;     // no continuation step is larger
  bool checks = true;            // closed form, lengths, rigid bodies, condition (off for timing)
  bool trace = false;            // record every attempt
};

// Solves start, start + step, ... up to stop (degrees). Throws std::invalid_argument for a
// step of zero or one that points away from stop.
MustangSweep mustang_sweep(MustangPoseSolver& solver, double start_deg, double stop_deg, double step_deg,
                           const MustangSweepOptions& options = {});

}  // namespace numlab::mechanisms
