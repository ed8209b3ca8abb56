// The trust-region dogleg's iteration: numlab/nonlinear/dogleg.hpp states the method, its steps
// numbered as below.

#include "numlab/nonlinear/dogleg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

namespace numlab::nonlinear {

Dogleg::Dogleg(const DynamicSystem& system, NewtonOptions options) : system_(system), options_(options) {
  require_tolerance(options_.residual_tolerance, "residual tolerance");
  require_tolerance(options_.step_tolerance, "step tolerance");
  if (options_.max_iterations < 1) {
    throw std::invalid_argument("iteration limit must be at least 1, got " + std::to_string(options_.max_iterations));
  }
}

void Dogleg::start(const Eigen::VectorXd& x0) {
  const int n = system_.dimension();
  if (x0.size() != n) {
    throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                std::to_string(n) + " unknowns");
  }
  linalg::require_finite(x0, "starting point");
  x_ = x0;
  f_.resize(n);
  trial_f_.resize(n);
  J_.resize(n, n);
  p_.resize(0);
  result_ = NewtonCounts{};  // status: running
  ratio_ = std::numeric_limits<double>::quiet_NaN();
  accepted_ = false;
  leg_ = DoglegLeg::none;
  if (observer_ != nullptr) started_at_ = std::chrono::steady_clock::now();  // only traces need the time
  system_.residual(x_, f_);
  ++result_.function_evaluations;
  radius_ = 100.0 * std::max(x_.norm(), 1.0);  // MINPACK's initial bound, factor 100
  running_ = true;
  stopped_ = false;
  if (!f_.allFinite()) {
    finish(StopReason::non_finite);
  } else if (residual_small(f_.lpNorm<Eigen::Infinity>(), options_.residual_tolerance)) {
    finish(StopReason::residual_small);
  }
}

bool Dogleg::step() {
  if (!running_) return false;
  ++result_.iterations;
  accepted_ = false;
  leg_ = DoglegLeg::none;

  // 1. J at x.
  system_.jacobian(x_, J_);
  ++result_.jacobian_evaluations;
  if (!J_.allFinite()) return finish(StopReason::non_finite);

  // 2. The Newton step p_N, when J can be solved: J p_N = -f by GEPP.
  const auto newton = gepp_.solve(J_, -f_);
  const bool has_newton = newton.status == Status::converged && newton.x.allFinite();

  // 3. The Cauchy step p_C along the steepest descent g = J^T f (zero when J g = 0).
  const Eigen::VectorXd g = J_.transpose() * f_;
  const double Jg = (J_ * g).squaredNorm();
  const Eigen::VectorXd cauchy =
      Jg > 0.0 ? Eigen::VectorXd(-(g.squaredNorm() / Jg) * g) : Eigen::VectorXd::Zero(f_.size());

  // 4. The dogleg step p inside the region; none at a stationary point of phi (g = 0).
  if (!choose_step(newton.x, has_newton, g, cauchy)) return finish(StopReason::step_small);

  // 5. Actual against predicted decrease of phi, at the trial point x + p.
  trial_x_ = x_ + p_;
  system_.residual(trial_x_, trial_f_);
  ++result_.function_evaluations;
  ratio_ = decrease_ratio();

  // 6. The radius follows how well the model predicted.
  const double length = p_.norm();
  if (ratio_ < 0.25) {
    radius_ = 0.25 * length;
  } else if (ratio_ > 0.75 && length >= 0.99 * radius_) {
    radius_ = 2.0 * radius_;
  }

  // 7. Accept the step when phi decreased enough.
  accepted_ = ratio_ > eta;
  if (accepted_) {
    x_ = trial_x_;
    f_ = trial_f_;
    result_.step_norm = p_.lpNorm<Eigen::Infinity>();
  }

  stop_tests();
  // After the tests: the observer sees the verdict (and may end the run here).
  if (notify(newton) == StepControl::stop && running_) {
    running_ = false;
    stopped_ = true;
  }
  return running_;
}

// Step 4: p_N if it lies in the region; else the steepest descent cut at the boundary if p_C lies
// outside it (or there is no p_N); else p_C + tau (p_N - p_C) on the boundary. False when g = 0.
bool Dogleg::choose_step(const Eigen::VectorXd& newton_step, bool has_newton, const Eigen::VectorXd& g,
                         const Eigen::VectorXd& cauchy) {
  if (has_newton && newton_step.norm() <= radius_) {
    p_ = newton_step;
    leg_ = DoglegLeg::newton;
  } else if (!has_newton || cauchy.norm() >= radius_) {
    if (g.norm() == 0.0) return false;  // a stationary point of phi
    p_ = -(radius_ / g.norm()) * g;
    leg_ = DoglegLeg::steepest_descent;
  } else {
    // tau in [0, 1] with ||p_C + tau d|| = radius, d = p_N - p_C: the positive root of a quadratic.
    const Eigen::VectorXd d = newton_step - cauchy;
    const double a = d.squaredNorm(), b = 2.0 * cauchy.dot(d), c = cauchy.squaredNorm() - radius_ * radius_;
    const double tau = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    p_ = cauchy + tau * d;
    leg_ = DoglegLeg::dogleg;
  }
  return true;
}

// Step 5: rho = (phi(x) - phi(x + p)) / (m(0) - m(p)); -infinity (no decrease) when f(x + p) is not
// finite or the model predicts none.
double Dogleg::decrease_ratio() const {
  const double phi = 0.5 * f_.squaredNorm();
  const double predicted = phi - 0.5 * (f_ + J_ * p_).squaredNorm();
  return trial_f_.allFinite() && predicted > 0.0 ? (phi - 0.5 * trial_f_.squaredNorm()) / predicted
                                                 : -std::numeric_limits<double>::infinity();
}

// The stop tests, in order: residual small, the region shrunk to nothing, the iteration limit.
void Dogleg::stop_tests() {
  result_.residual_norm = f_.lpNorm<Eigen::Infinity>();
  if (residual_small(result_.residual_norm, options_.residual_tolerance)) {
    finish(StopReason::residual_small);
  } else if (step_small(radius_, x_.lpNorm<Eigen::Infinity>(), options_.step_tolerance)) {
    finish(StopReason::step_small);  // Delta <= step_tolerance (1 + ||x||_inf), yet ||f|| is not small
  } else if (result_.iterations >= options_.max_iterations) {
    finish(StopReason::iteration_limit);
  }
}

bool Dogleg::finish(StopReason reason) {
  result_.status = status_of(reason);
  result_.reason = reason;
  running_ = false;
  return false;
}

StepControl Dogleg::notify(const linalg::LinearResult<Eigen::Dynamic>& newton) {
  if (observer_ == nullptr) return StepControl::proceed;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
  const double taken = accepted_ ? 1.0 : 0.0;  // the fraction of p taken: damping in the record
  const double moved = accepted_ ? p_.lpNorm<Eigen::Infinity>() : 0.0;
  return observer_->on_step(*this, {result_.iterations, result_.residual_norm, f_.norm(), moved, newton.status,
                                    newton.iterations, taken, elapsed, std::numeric_limits<double>::quiet_NaN(),
                                    NewtonRecord::every_iteration});
}

NewtonResult<Eigen::Dynamic> Dogleg::solve(const Eigen::VectorXd& x0) {
  start(x0);
  while (step()) {
  }
  return result();
}

NewtonResult<Eigen::Dynamic> Dogleg::result() const {
  NewtonResult<Eigen::Dynamic> result{result_, x_};
  result.residual_norm = f_.lpNorm<Eigen::Infinity>();
  return result;
}

}  // namespace numlab::nonlinear
