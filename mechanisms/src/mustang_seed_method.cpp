#include "numlab/mechanisms/mustang_seed_method.hpp"

#include <algorithm>
#include <cmath>

#include "numlab/linalg/inverse2x2.hpp"

namespace numlab::mechanisms {

SeedMethodPose seed_method_pose(double theta, const SeedMethodOptions& options, const MustangAngles& previous) {
  const MustangClosure closure(theta);
  // The seed's rounded chord in loop 2: |2 6| = 4.698 instead of 2 (2.5) cos 20 = 4.69846.
  const double bent = theta + closure.lengths().bend;
  const Eigen::Vector2d rounding = (4.698 - closure.lengths().chord2_6()) * Eigen::Vector2d(std::cos(bent), std::sin(bent));

  SeedMethodPose pose;
  pose.x = options.restart ? MustangClosure::seed_guess() : previous;
  for (int k = 0; k < MustangClosure::loops; ++k) {
    SeedLoopRun& run = pose.loops[static_cast<std::size_t>(k)];
    MustangLoop loop;
    loop.terms = closure.loop(k, pose.x);
    if (options.rounded && k == 1) loop.terms.known += rounding;
    Eigen::Vector2d v = pose.x.segment<2>(2 * k), f;
    Eigen::Matrix2d J;
    auto test_of = [&](const Eigen::Vector2d& values) {
      return options.sum_test ? std::abs(values(0) + values(1)) : values.lpNorm<Eigen::Infinity>();
    };
    loop.residual_and_jacobian(v, f, J);
    while (true) {
      // 1. The seed's test: stop when it is at or below 0.001.
      run.test_value = test_of(f);
      run.residual_norm = f.lpNorm<Eigen::Infinity>();
      if (!f.allFinite() || !v.allFinite()) {
        run.status = Status::non_finite;
        break;
      }
      if (run.test_value <= options.tolerance) break;
      if (run.iterations >= options.max_iterations) {
        run.status = Status::max_iterations;
        break;
      }
      // 2. The Jacobian (evaluated with f), as the seed wrote it or corrected.
      if (options.seed_jacobian && k == 2) J.row(1) *= -1.0;                  // Df3_j, both signs flipped
      if (options.seed_jacobian && k == 3) J(1, 1) = -std::cos(pose.x(3));    // Df4_j(2) = -cos(D)
      // 3. The closed-form inverse and the Newton step v <- v - J^-1 f.
      const linalg::Inverse2x2 inverse = linalg::inverse2x2(J);
      if (inverse.status != Status::converged) {
        run.status = Status::singular;
        break;
      }
      v -= inverse.inverse * f;
      loop.residual_and_jacobian(v, f, J);
      ++run.iterations;
    }
    pose.x.segment<2>(2 * k) = v;
    if (run.status != Status::converged && pose.status == Status::converged) pose.status = run.status;
  }
  MustangClosure::Vector f;
  closure.residual(pose.x, f);  // the exact equations
  pose.residual_norm = f.allFinite() ? f.lpNorm<Eigen::Infinity>() : std::numeric_limits<double>::infinity();
  return pose;
}

}  // namespace numlab::mechanisms
