#pragma once
// The pose-solver layer both linkages share: one outcome type and one interface. A pose solver
// finds the angles that close a linkage at one input (crank) angle, starting from a guess.
//
// Its implementations are written once for both linkages where they can be:
// full_newton_pose_solver.hpp (Newton on the whole closure) and gsl_pose_solver.hpp (GSL's
// multiroot solvers); the sequential and analytic solvers know their linkage's structure and
// live beside it (jansen_solvers.cpp, mustang_solvers.cpp).

#include "numlab/status.hpp"

namespace numlab::mechanisms {

// How one pose solve went.
struct PoseOutcome {
  Status status = Status::running;  // until the solver sets its verdict
  int iterations = 0;
  double residual_norm = 0.0;  // ||f||_inf of the whole closure at the end
};

// Angles: the linkage's unknowns (an Eigen vector).
template <typename Angles>
class PoseSolver {
 public:
  virtual ~PoseSolver() = default;
  // Solves the closure at `input_angle` (radians), starting from `x`, which it overwrites.
  virtual PoseOutcome solve(double input_angle, Angles& x) = 0;
  // A solver that works loop by loop (the Mustang's sequential and analytic): the loop (1 ...)
  // that its last solve could not close, else 0.
  int failed_loop() const { return failed_loop_; }

 protected:
  int failed_loop_ = 0;
};

}  // namespace numlab::mechanisms
