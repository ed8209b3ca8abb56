#pragma once
// Seed 003's method as the seed wrote it, kept to show where and why it fails (lab `mustang`).
// Each error can be switched off on its own:
//  - restart: every loop starts from [pi/18, pi/2] at every theta (no continuation);
//  - sum_test: Newton stops when |f_i + f_j| <= 0.001, so the two components may cancel;
//  - seed_jacobian: loop 3's second Jacobian row has both signs flipped
//    (Df3_j = [-4.5 cos E, (4/3) cos F], correct [4.5 cos E, -(4/3) cos F]) and loop 4's
//    d f4_j / d H reads D where H belongs (Df4_j(2) = -cos(v2(2)));
//  - rounded: the seed's constants 4.698 for |2 6|.
// The seed's loop has no iteration limit; here it stops after `max_iterations` (the seed's
// program hung there) and says so.

#include <array>

#include "numlab/mechanisms/mustang_linkage.hpp"

namespace numlab::mechanisms {

struct SeedMethodOptions {
  bool restart = true;
  bool sum_test = true;
  bool seed_jacobian = true;
  bool rounded = true;
  double tolerance = 0.001;  // the seed's
  int max_iterations = 500;
};

struct SeedLoopRun {
  Status status = Status::converged;  // converged (its test passed), max_iterations, singular, non_finite
  int iterations = 0;
  double test_value = 0.0;    // what the seed's test saw at the end: |f_i + f_j| (or max |f|)
  double residual_norm = 0.0;  // max(|f_i|, |f_j|) at the end
};

struct SeedMethodPose {
  MustangAngles x;
  std::array<SeedLoopRun, 4> loops;
  Status status = Status::converged;  // the first loop's failure, if any
  double residual_norm = 0.0;          // of all eight exact equations (MustangClosure) at x
};

// One pose at theta (radians). `previous` is the start when restart is off.
SeedMethodPose seed_method_pose(double theta, const SeedMethodOptions& options,
                                const MustangAngles& previous = MustangClosure::seed_guess());

}  // namespace numlab::mechanisms
