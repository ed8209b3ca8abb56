#pragma once
// Trust-region dogleg Newton (Powell's hybrid idea, as in Nocedal & Wright, "Numerical
// Optimization", 2nd ed., Algorithms 4.1 and 11.5), written by hand: the method behind MINPACK's
// hybrj and GSL's hybrid types, here without their scaling and Broyden updates.
//
// The merit is phi(x) = 1/2 ||f(x)||_2^2 and the model of it around x is
// m(p) = 1/2 ||f + J p||_2^2. Each iteration, with trust radius Delta:
//   1. J at x.
//   2. The Newton step p_N: J p_N = -f (GEPP); none when J is singular.
//   3. The Cauchy step p_C: the model's minimiser along the steepest descent g = J^T f,
//      p_C = -(||g||^2 / ||J g||^2) g.
//   4. The dogleg step p: p_N if it lies in the region; else the steepest descent cut at the
//      boundary if p_C lies outside it; else p_C + tau (p_N - p_C) with ||p|| = Delta.
//   5. The ratio rho = (phi(x) - phi(x + p)) / (m(0) - m(p)) of actual to predicted decrease.
//   6. The radius: shrink to ||p|| / 4 when rho < 1/4; double when rho > 3/4 and p reached the
//      boundary.
//   7. Accept x + p when rho > eta (= 1e-4); otherwise stay.
//   until ||f(x)||_inf <= residual_tolerance                -> converged (residual_small)
//      or Delta <= step_tolerance (1 + ||x||_inf)            -> no_progress (step_small): the region
//         shrank to nothing at a point that is not a root (a local minimum of ||f||, say)
//      or the iteration limit                               -> max_iterations
// The first radius is MINPACK's: 100 max(||x0||_2, 1). A trial point where f is not finite counts as
// no decrease (rho = -infinity): the region shrinks.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

// NewtonOptions' tolerances and iteration limit apply; `damped` and the halving limit do not.
// Throws std::invalid_argument for a wrong-sized or non-finite x0, or options Newton rejects.
inline NewtonResult<Eigen::Dynamic> dogleg_solve(const DynamicSystem& system, const Eigen::VectorXd& x0,
                                                 const NewtonOptions& options = {}) {
  require_tolerance(options.residual_tolerance, "residual tolerance");
  require_tolerance(options.step_tolerance, "step tolerance");
  if (options.max_iterations < 1) throw std::invalid_argument("iteration limit must be at least 1");
  const int n = system.dimension();
  if (x0.size() != n) throw std::invalid_argument("starting point has the wrong number of entries");
  linalg::require_finite(x0, "starting point");
  constexpr double eta = 1e-4;

  NewtonResult<Eigen::Dynamic> result;
  result.x = x0;
  Eigen::VectorXd f(n), trial_f(n);
  Eigen::MatrixXd J(n, n);
  system.residual(result.x, f);
  ++result.function_evaluations;
  double radius = 100.0 * std::max(result.x.norm(), 1.0);  // MINPACK's initial bound, factor 100
  linalg::GaussElimination<Eigen::Dynamic> gepp;
  auto finish = [&](StopReason reason) {
    result.status = status_of(reason);
    result.reason = reason;
    result.residual_norm = f.lpNorm<Eigen::Infinity>();
    return result;
  };
  if (!f.allFinite()) return finish(StopReason::non_finite);
  while (true) {
    if (residual_small(f.lpNorm<Eigen::Infinity>(), options.residual_tolerance)) {
      return finish(StopReason::residual_small);
    }
    if (result.iterations >= options.max_iterations) return finish(StopReason::iteration_limit);
    ++result.iterations;

    // 1. J at x.
    system.jacobian(result.x, J);
    ++result.jacobian_evaluations;
    if (!J.allFinite()) return finish(StopReason::non_finite);

    // 2. The Newton step, when J can be solved.
    const auto newton = gepp.solve(J, -f);
    const bool has_newton = newton.status == Status::converged && newton.x.allFinite();

    // 3. The Cauchy step along g = J^T f.
    const Eigen::VectorXd g = J.transpose() * f;
    const double Jg = (J * g).squaredNorm();
    const Eigen::VectorXd cauchy = Jg > 0.0 ? Eigen::VectorXd(-(g.squaredNorm() / Jg) * g) : Eigen::VectorXd::Zero(n);

    // 4. The dogleg step inside the region.
    Eigen::VectorXd p;
    if (has_newton && newton.x.norm() <= radius) {
      p = newton.x;
    } else if (!has_newton || cauchy.norm() >= radius) {
      if (g.norm() == 0.0) return finish(StopReason::step_small);  // a stationary point of phi
      p = -(radius / g.norm()) * g;
    } else {
      // tau in [0, 1] with ||p_C + tau d|| = radius, d = p_N - p_C: the positive root of a quadratic.
      const Eigen::VectorXd d = newton.x - cauchy;
      const double a = d.squaredNorm(), b = 2.0 * cauchy.dot(d), c = cauchy.squaredNorm() - radius * radius;
      const double tau = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
      p = cauchy + tau * d;
    }

    // 5. Actual against predicted decrease of phi.
    const Eigen::VectorXd trial_x = result.x + p;
    system.residual(trial_x, trial_f);
    ++result.function_evaluations;
    const double phi = 0.5 * f.squaredNorm();
    const double predicted = phi - 0.5 * (f + J * p).squaredNorm();
    const double rho = trial_f.allFinite() && predicted > 0.0 ? (phi - 0.5 * trial_f.squaredNorm()) / predicted
                                                              : -std::numeric_limits<double>::infinity();

    // 6. The radius follows how well the model predicted.
    const double length = p.norm();
    if (rho < 0.25) {
      radius = 0.25 * length;
    } else if (rho > 0.75 && length >= 0.99 * radius) {
      radius = 2.0 * radius;
    }

    // 7. Accept the step when phi decreased enough.
    if (rho > eta) {
      result.x = trial_x;
      f = trial_f;
      result.step_norm = p.lpNorm<Eigen::Infinity>();
    }
    if (step_small(radius, result.x.lpNorm<Eigen::Infinity>(), options.step_tolerance) &&
        !residual_small(f.lpNorm<Eigen::Infinity>(), options.residual_tolerance)) {
      return finish(StopReason::step_small);
    }
  }
}

}  // namespace numlab::nonlinear
