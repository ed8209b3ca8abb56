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
// no decrease (rho = -infinity): the region shrinks. Two more endings, each after no move: J not
// finite (non_finite), and g = 0 with no Newton step inside the region, a stationary point of phi
// that is not a root (step_small).
//
// A stepper (numlab/solver.hpp): one step() is one iteration, steps 1-7 and the stop tests
// (src/dogleg.cpp); status() is Status::running until the iteration has ended. Each step that
// reached step 7 sends a NewtonRecord to the observer, after the stop tests:
//   residual_norm, residual_2norm   ||f||_inf and ||f||_2 at x after the step (unchanged when rejected);
//   step_norm                       how far x moved, ||damping * p||_inf;
//   damping                         1 when the step was accepted, 0 when rejected (x stays): the
//                                   fraction of p taken, as Newton's lambda is the fraction of dx;
//   linear_status, linear_iterations  GEPP's solve for p_N (singular: no Newton step, the dogleg
//                                   used the steepest descent) and its pivot columns;
//   forcing_term NaN (an exact solve), jacobian_refactored every_iteration.
// The trust region's own numbers are the stepper's, read by an observer from the Dogleg it is
// given: radius() (Delta for the next step), ratio() (rho), accepted(), leg() and trial_step() (p).

#include <Eigen/Core>
#include <chrono>
#include <limits>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/stop_reason.hpp"
#include "numlab/nonlinear/system.hpp"
#include "numlab/solver.hpp"

namespace numlab::nonlinear {

// Which part of the dogleg path step 4 took.
enum class DoglegLeg {
  none,               // no step yet (or the last step ended before step 4)
  newton,             // p = p_N: the Newton step lies in the region
  steepest_descent,   // p = -(Delta / ||g||) g: the steepest descent cut at the boundary
  dogleg              // p = p_C + tau (p_N - p_C) on the boundary
};

class Dogleg {
 public:
  using Observer = StepObserver<Dogleg, NewtonRecord>;
  static constexpr double eta = 1e-4;  // step 7: the least rho that accepts a step

  // NewtonOptions' tolerances and iteration limit apply; `damped`, the halving limit, the divergence
  // factor, forcing and Jacobian reuse do not. Throws std::invalid_argument for options Newton rejects
  // (a tolerance negative or not finite, an iteration limit below 1).
  explicit Dogleg(const DynamicSystem& system, NewtonOptions options = {});
  // The stepper keeps a reference to the system: a temporary would dangle, so it is refused.
  explicit Dogleg(const DynamicSystem&&, NewtonOptions = {}) = delete;

  void set_observer(Observer* observer) { observer_ = observer; }

  // Sets x = x0, evaluates f(x0) and the first radius. Throws std::invalid_argument for a wrong
  // size or non-finite x0.
  void start(const Eigen::VectorXd& x0);
  // One trust-region iteration. Returns false once the iteration has ended.
  bool step();
  NewtonResult<Eigen::Dynamic> solve(const Eigen::VectorXd& x0);
  NewtonResult<Eigen::Dynamic> result() const;

  // State between iterations.
  bool running() const { return running_; }
  Status status() const { return result_.status; }  // running until the iteration has ended
  bool stopped() const { return stopped_; }
  int iterations() const { return result_.iterations; }
  const Eigen::VectorXd& x() const { return x_; }
  const Eigen::VectorXd& residual() const { return f_; }
  const Eigen::MatrixXd& jacobian() const { return J_; }
  const NewtonOptions& options() const { return options_; }

  // The trust region, for a trace.
  double radius() const { return radius_; }              // Delta for the next step (after step 6)
  double ratio() const { return ratio_; }                // rho of the last step; NaN before the first
  bool accepted() const { return accepted_; }            // whether the last step moved x
  DoglegLeg leg() const { return leg_; }                 // which part of the path the last step took
  const Eigen::VectorXd& trial_step() const { return p_; }  // p of the last step

 private:
  bool choose_step(const Eigen::VectorXd& newton_step, bool has_newton, const Eigen::VectorXd& g,
                   const Eigen::VectorXd& cauchy);
  double decrease_ratio() const;
  void stop_tests();
  bool finish(StopReason reason);
  StepControl notify(const linalg::LinearResult<Eigen::Dynamic>& newton);

  const DynamicSystem& system_;
  NewtonOptions options_;
  linalg::GaussElimination<Eigen::Dynamic> gepp_;
  Observer* observer_ = nullptr;
  Eigen::VectorXd x_, f_, p_, trial_x_, trial_f_;
  Eigen::MatrixXd J_;
  NewtonCounts result_;
  double radius_ = 0.0;
  double ratio_ = std::numeric_limits<double>::quiet_NaN();
  bool accepted_ = false;
  DoglegLeg leg_ = DoglegLeg::none;
  bool running_ = false;
  bool stopped_ = false;
  std::chrono::steady_clock::time_point started_at_;
};

// A Dogleg's solve(): throws as its constructor and start() do.
inline NewtonResult<Eigen::Dynamic> dogleg_solve(const DynamicSystem& system, const Eigen::VectorXd& x0,
                                                 const NewtonOptions& options = {}) {
  return Dogleg(system, options).solve(x0);
}

}  // namespace numlab::nonlinear
