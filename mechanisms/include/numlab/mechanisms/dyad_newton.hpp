#pragma once
// Newton's method on one dyad (dyad_block.hpp), the block of seed 000's sequential solve.
// Specialised copy of Newton<DyadBlock, ClosedForm2x2>; equality tested in tests/mechanisms/test_dyad_newton.cpp.
//
//   f(alpha, beta) = k + p u(alpha) - q u(beta),   u(t) = (sin t, cos t)  (sine row first)
//   repeat:  solve J dx = -f by the closed-form 2x2 inverse (linalg::ClosedForm2x2),  x <- x + dx
//   until    a stopping test of stopping_tests.hpp ends it, in Newton's order.
//
// The same options, stopping tests, statuses and stepper shape (start, step, solve, state readable
// between steps) as the generic Newton; no damping (a crank sweep halves its step instead), so
// NewtonOptions::damped is rejected. Fast path: its state is a few scalars, and its sines and
// cosines come from a cache kept from step to step and pose to pose (anchored_sincos.hpp).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "numlab/force_inline.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/anchored_sincos.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

namespace numlab::mechanisms {

class DyadNewton {
 public:
  // Throws std::invalid_argument for options Newton rejects, and for damping (not available here).
  explicit DyadNewton(const nonlinear::NewtonOptions& options = {}) : options_(options) {
    nonlinear::require_tolerance(options_.residual_tolerance, "residual tolerance");
    nonlinear::require_tolerance(options_.step_tolerance, "step tolerance");
    if (options_.max_iterations < 1) {
      throw std::invalid_argument("iteration limit must be at least 1, got " + std::to_string(options_.max_iterations));
    }
    if (options_.damped) {
      throw std::invalid_argument("damping is not available for the dyad's Newton (sequential Jansen solver): "
                                  "it takes full steps, and a sweep halves its crank step instead");
    }
  }

  // The block: known part k = (k_y, k_x) and the lengths p, q.
  void set_block(double known_y, double known_x, double p, double q) {
    known_y_ = known_y;
    known_x_ = known_x;
    p_ = p;
    q_ = q;
  }

  // Sets x = (alpha, beta) and evaluates f there.
  void start(double alpha, double beta) {
    place(alpha, beta);
    start_placed();
  }

  // The first half of start(): x = (alpha, beta) and the sines and cosines there, which is all of
  // the first evaluation (and of the first J) that the known part does not enter. A caller solving
  // blocks in turn can place every block first: their sines do not wait for the blocks before.
  NUMLAB_FORCE_INLINE void place(double alpha, double beta) {
    alpha_ = alpha;
    beta_ = beta;
    sines_.evaluate(Eigen::Vector2d(alpha_, beta_), cos_, sin_);
  }

  // The second half: f at the placed point, with the block given by set_block().
  void start_placed() {
    iterations_ = 0;
    step_norm_ = 0.0;
    running_ = true;
    status_ = Status::running;
    evaluate_residual();
    residual_at_start_ = residual_norm_;
    if (!std::isfinite(residual_norm_)) {
      finish(Status::non_finite);
    } else if (nonlinear::residual_small(residual_norm_, options_.residual_tolerance)) {
      finish(Status::converged);
    }
  }

  // One Newton iteration. Returns false once the iteration has ended.
  bool step() {
    if (!running_) return false;
    ++iterations_;
    // 1. The Jacobian at x, from the sines and cosines of the last evaluation.
    Eigen::Matrix2d J;
    J << p_ * cos_(0), -q_ * cos_(1), -p_ * sin_(0), q_ * sin_(1);
    // 2. The Newton step: J dx = -f by the closed form.
    const auto linear = linalg::ClosedForm2x2().solve_prechecked(J, Eigen::Vector2d(-f_y_, -f_x_));
    if (linear.status != Status::converged) return finish(linear.status);
    // 3. Move, and evaluate f at the new point.
    alpha_ += linear.x(0);
    beta_ += linear.x(1);
    step_norm_ = linear.x.lpNorm<Eigen::Infinity>();
    evaluate();
    // 4. Stop tests, in Newton's order.
    if (!std::isfinite(residual_norm_)) return finish(Status::non_finite);
    if (nonlinear::residual_small(residual_norm_, options_.residual_tolerance)) return finish(Status::converged);
    if (nonlinear::step_small(step_norm_, std::max(std::abs(alpha_), std::abs(beta_)), options_.step_tolerance)) {
      return finish(Status::no_progress);  // a small step is not a root
    }
    if (nonlinear::diverged(residual_norm_, residual_at_start_, options_.divergence_factor)) {
      return finish(Status::diverged);
    }
    if (iterations_ >= options_.max_iterations) return finish(Status::max_iterations);
    return true;
  }

  Status solve(double alpha, double beta) {
    place(alpha, beta);
    return solve_placed();
  }

  // start_placed(), then step() until the iteration ends.
  Status solve_placed() {
    start_placed();
    while (step()) {
    }
    return status_;
  }

  // State between iterations.
  bool running() const { return running_; }
  Status status() const { return status_; }  // Status::running until the iteration has ended
  bool stopped() const { return false; }      // no observer: nothing can end the run early
  int iterations() const { return iterations_; }
  Eigen::Vector2d x() const { return {alpha_, beta_}; }
  double alpha() const { return alpha_; }
  double beta() const { return beta_; }
  double residual_norm() const { return residual_norm_; }  // ||f||_inf at the current point
  double step_norm() const { return step_norm_; }          // ||dx||_inf of the last step
  // u(alpha) (which = 0) or u(beta) (1) at the current point, in (y, x) order: the direction a
  // later block needs, without computing its sine and cosine again.
  Eigen::Vector2d direction(int which) const { return {sin_(which), cos_(which)}; }

 private:
  NUMLAB_FORCE_INLINE void evaluate() {
    sines_.evaluate(Eigen::Vector2d(alpha_, beta_), cos_, sin_);
    evaluate_residual();
  }

  // f and ||f||_inf from the sines and cosines at the current point.
  void evaluate_residual() {
    f_y_ = known_y_ + p_ * sin_(0) - q_ * sin_(1);
    f_x_ = known_x_ + p_ * cos_(0) - q_ * cos_(1);
    residual_norm_ = std::max(std::abs(f_y_), std::abs(f_x_));
    if (std::isnan(f_y_ + f_x_)) residual_norm_ = std::numeric_limits<double>::quiet_NaN();  // max() drops a NaN
  }

  bool finish(Status status) {
    status_ = status;
    running_ = false;
    return false;
  }

  nonlinear::NewtonOptions options_;
  double known_y_ = 0.0, known_x_ = 0.0, p_ = 0.0, q_ = 0.0;
  double alpha_ = 0.0, beta_ = 0.0, f_y_ = 0.0, f_x_ = 0.0;
  double residual_norm_ = 0.0, residual_at_start_ = 0.0, step_norm_ = 0.0;
  Eigen::Vector2d cos_ = Eigen::Vector2d::Zero(), sin_ = Eigen::Vector2d::Zero();  // at the current point
  AnchoredSinCos<2> sines_;
  int iterations_ = 0;
  Status status_ = Status::running;  // no verdict before a solve has finished
  bool running_ = false;
};

}  // namespace numlab::mechanisms
