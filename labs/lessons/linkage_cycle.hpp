#pragma once
// A derived linkage model over equal driver steps, solved the way `numlab bench jansen` times the
// hand-written Jansen models: each pose from the polynomial through the poses before it, and nothing
// else computed (no velocities, kappa(J), branch or closed-form checks: linkage_sweep() does those).
// The linkage lab times this, so that the derived model and the seeds' models do the same work.

#include <Eigen/Core>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::cli {

struct LinkageCycle {
  Eigen::MatrixXd q;            // column k: the unknowns of pose k (only the first `solved` are poses)
  std::vector<double> driver;   // pose k's driver value, user units (degrees of crank)
  int solved = 0;
  int iterations = 0;           // summed over the poses
  Status status = Status::converged;  // the first pose that failed stops the cycle with its status
};

// Solves the poses start, start + step, ... (`poses` of them, user units), the first from the
// solver's reference pose, each later one from the prediction:
//   1. predict: the polynomial through the last m solved poses (m <= 5, degree m - 1), one step on;
//   2. correct: the solver's solve() from that prediction, on its fast path (LinkageFastSolver: the
//      same solves, iterations and statuses, on a workspace sized once) where that applies, as
//      `numlab bench jansen` solves the file.
// No step halving: a pose that fails ends the cycle.
LinkageCycle solve_linkage_cycle(const mechanisms::LinkageSolver& solver, double start, double step, int poses);

}  // namespace numlab::cli
