#pragma once
// Internal to the linkage fast path (linkage_fast_solver.cpp): a constraint's rows and their
// derivatives one at a time, Phi whole, GEPP in place that skips zero multipliers, and the Newton
// loop, in place. Nothing here allocates.

#include <Eigen/Core>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

namespace numlab::mechanisms::detail {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Constraint c's rows at q (a one-row constraint leaves the second 0): the rows of LinkageModel::residual,
// with the crank's direction (cos, sin)(t + offset) given, computed once per solve.
Eigen::Vector2d rows_of(const LinkageModel& model, const Constraint& c, const Eigen::VectorXd& q, double t,
                        const Eigen::Vector2d& crank_direction);

// d(rows of c) / d(joint's x, y) at (q, t): the blocks LinkageModel::jacobian puts in J; zero for a
// joint c does not read. Only a motor's depend on t.
Eigen::Matrix2d partial_of(const LinkageModel& model, const Constraint& c, const Eigen::VectorXd& q, double t, int joint);

// Phi(q; t), every constraint once, into f (sized to the equations).
void whole_residual(const LinkageModel& model, const Eigen::VectorXd& q, double t, const Eigen::Vector2d& crank_direction,
                    Eigen::VectorXd& f);

// GEPP as gauss_elimination_kernel.hpp runs it (the same pivots, multipliers and order of
// operations), except that a row whose multiplier is zero is left alone: a derived J has a few
// nonzeros per column (the Jansen leg's 36 of 144), so most row updates are skipped.
// J dx = -f with J in `work` (overwritten by U); pivots negligible below n eps max|J|.
Status sparse_gepp(RowMajorMatrix& work, const Eigen::VectorXd& f, Eigen::VectorXd& rhs, Eigen::VectorXd& inverse_pivots,
                   Eigen::VectorXd& dx);

// Undamped Newton with a direct inner solve, in place on x: the loop of nonlinear::Newton
// (newton.hpp) with the same tests in the same order and the same counts, but for J: evaluated once
// per iteration here, where Newton on a DynamicSystem evaluates it with every residual. The problem gives
// residual(x, f), jacobian(x) (false when J is not finite) and solve(f, dx) (J dx = -f, a status).
template <typename Problem, typename Vector>
nonlinear::NewtonCounts newton_in_place(Problem& problem, Vector& x, Vector& f, Vector& dx, const nonlinear::NewtonOptions& options) {
  nonlinear::NewtonCounts counts;
  const auto finish = [&](Status status, nonlinear::StopReason reason) {
    counts.status = status;
    counts.reason = reason;
    counts.residual_norm = f.template lpNorm<Eigen::Infinity>();
    return counts;
  };
  problem.residual(x, f);
  ++counts.function_evaluations;
  const double at_start = f.template lpNorm<Eigen::Infinity>();
  if (!linalg::all_finite(f)) return finish(Status::non_finite, nonlinear::StopReason::non_finite);
  if (nonlinear::residual_small(at_start, options.residual_tolerance)) return finish(Status::converged, nonlinear::StopReason::residual_small);
  while (true) {
    ++counts.iterations;
    ++counts.jacobian_evaluations;
    if (!problem.jacobian(x)) return finish(Status::non_finite, nonlinear::StopReason::non_finite);
    const Status linear = problem.solve(f, dx);
    if (linear == Status::singular) return finish(Status::singular, nonlinear::StopReason::singular_jacobian);
    if (linear != Status::converged || !linalg::all_finite(dx)) return finish(Status::non_finite, nonlinear::StopReason::non_finite);
    x += dx;
    problem.residual(x, f);
    ++counts.function_evaluations;
    counts.step_norm = dx.template lpNorm<Eigen::Infinity>();
    const double residual = f.template lpNorm<Eigen::Infinity>();
    if (!linalg::all_finite(x) || !linalg::all_finite(f)) return finish(Status::non_finite, nonlinear::StopReason::non_finite);
    if (nonlinear::residual_small(residual, options.residual_tolerance)) return finish(Status::converged, nonlinear::StopReason::residual_small);
    if (nonlinear::step_small(counts.step_norm, x.template lpNorm<Eigen::Infinity>(), options.step_tolerance)) {
      return finish(Status::no_progress, nonlinear::StopReason::step_small);
    }
    if (nonlinear::diverged(residual, at_start, options.divergence_factor)) return finish(Status::diverged, nonlinear::StopReason::diverged);
    if (counts.iterations >= options.max_iterations) return finish(Status::max_iterations, nonlinear::StopReason::iteration_limit);
  }
}

}  // namespace numlab::mechanisms::detail
