#pragma once
// Full Newton-Raphson (seed 000 Listing 1, seed 001 jansen_estimate), with any linear solver:
//
//   repeat:  solve J(x) dx = -f(x)      (GEPP, Gauss-Seidel, GSL LU, Eigen LU, 2x2 closed form;
//                                        an iterative solver only to ||J dx + f|| <= eta_k ||f||,
//                                        eta_k the forcing term of forcing_term.hpp: inexact Newton)
//            x <- x + lambda dx         (lambda = 1; with damping, the first of 1, 1/2, 1/4, ...
//                                        that passes Armijo's sufficient decrease on ||f||_2^2)
//   until    ||f(x)||_inf <= residual_tolerance            -> converged (residual_small)
//         or ||dx||_inf <= step_tolerance (1 + ||x||_inf)  -> no_progress (step_small): the
//            iterates stopped moving, but a small step is not a root; only the residual test
//            gives converged
//
// The chord method (Shamanskii's, reuse_jacobian = K > 1): J is evaluated and factored only every
// K-th iteration (1, K+1, 2K+1, ...); the iterations between solve J_old dx = -f with the kept
// factors (GEPP's solve_with_factors). Cheaper iterations, converging linearly rather than
// quadratically: more of them, fewer factorizations. K = 1 is Newton.
//
// Other endings, each a status with the numbers behind it: max_iterations; singular (the linear
// solve found J singular); non_finite (f, J or x stopped being finite); diverged (||f||_inf grew
// past divergence_factor times its start); no_progress (damping found no sufficient decrease).
// The tests are the named functions of stopping_tests.hpp.
//
// A stepper (numlab/solver.hpp): one step() is one iteration; status() is Status::running until
// the iteration has ended. Fixed sizes allocate nothing on the heap, in start() or step().

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/forcing_term.hpp"
#include "numlab/nonlinear/stop_reason.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"
#include "numlab/nonlinear/system.hpp"
#include "numlab/solver.hpp"

namespace numlab::nonlinear {

struct NewtonOptions {
  double residual_tolerance = 1e-9;  // seed 001's accuracy (seed 000 used 1e-5)
  double step_tolerance = 1e-12;     // relative: ||dx|| <= tol (1 + ||x||)
  int max_iterations = 20;           // seed 001's limit (seed 000 used 10)
  bool damped = false;               // backtracking (Armijo on ||f||_2^2), off by default
  int max_halvings = 30;             // damping gives up (no_progress) after this many
  double divergence_factor = 1e12;   // diverged when ||f|| > factor * max(||f(x0)||, 1)
  ForcingOptions forcing;            // an iterative inner solve's eta_k (Eisenstat-Walker by default);
                                     // direct solvers ignore it
  bool stop_on_failed_inner_step = false;  // end at the first capped inner solve whose step does not
                                           // decrease ||f|| (inner_step_failed); off: only the three-in-a-row rule
  int reuse_jacobian = 1;  // K: J evaluated and factored every K iterations, its factors reused between
                           // (chord / Shamanskii); 1: Newton. K > 1 needs a linear step that keeps its factors
};

// A linear step that keeps the factors of its last J and solves another right-hand side with them.
template <typename Step, typename V>
concept KeepsFactors = requires(const Step& step, const V& rhs) { step.solve_with_factors(rhs); };

// A linear step that can be told a relative residual target (an iterative one: Gauss-Seidel, or
// RuntimeLinearStep, which says whether its method is iterative).
template <typename Step>
concept TakesForcingTerm = requires(Step& step, double eta) { step.set_relative_residual_tolerance(eta); };

// The bookkeeping of a Newton run: everything in its result but x. Shared by numlab's Newton and
// GSL's multiroot adapter (gsl_multiroot.hpp).
struct NewtonCounts {
  Status status = Status::running;
  StopReason reason = StopReason::running;
  int iterations = 0;
  double residual_norm = std::numeric_limits<double>::quiet_NaN();  // ||f(x)||_inf at the end
  double step_norm = std::numeric_limits<double>::quiet_NaN();      // ||dx||_inf of the last step
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
  int factorizations = 0;  // linear solves with a new J (Newton's direct solves: one per iteration)
  std::string_view message;  // GSL's own words (a static string) when it stopped on an error; else empty
};

template <int N>
struct NewtonResult : NewtonCounts {
  Vector<N> x = Vector<N>::Zero(N == Eigen::Dynamic ? 0 : N);
};

// One row of the trace, sent after every iteration (by Newton, GSL's adapter and sequential Newton).
struct NewtonRecord {
  static constexpr int no_linear_solve = -1;  // linear_iterations of a method without one (GSL's)
  int iteration;
  double residual_norm;    // ||f||_inf after the step
  double residual_2norm;   // ||f||_2 after the step
  double step_norm;        // ||lambda dx||_inf
  Status linear_status;    // of the inner solve J dx = -f
  int linear_iterations;   // sweeps, for Gauss-Seidel
  double damping;          // lambda (1 unless damped)
  double elapsed_s;        // since start()
  double forcing_term = std::numeric_limits<double>::quiet_NaN();  // eta_k; NaN: exact inner solve
  static constexpr int every_iteration = -1;  // jacobian_refactored when J is new at every iteration
  int jacobian_refactored = every_iteration;  // chord (reuse_jacobian > 1): 1 J evaluated and factored, 0 reused
};

// "Termination: CONVERGED (||f||_inf = 3e-13 <= 1e-09 after 5 iterations)" and the like.
template <int N>
std::string termination_line(const NewtonResult<N>& result, const NewtonOptions& options);

template <NonlinearSystem S, typename LinearStep = linalg::GaussElimination<S::size>>
class Newton {
 public:
  static constexpr int N = S::size;
  using Observer = StepObserver<Newton, NewtonRecord>;

  // The linear step is built in place (its default); or passed in, for one that needs arguments.
  explicit Newton(const S& system, NewtonOptions options = {})
      : system_(system), options_(options), forcing_(options.forcing) {
    check_options();
  }
  Newton(const S& system, NewtonOptions options, LinearStep linear_step)
      : system_(system), options_(options), linear_step_(std::move(linear_step)), forcing_(options.forcing) {
    check_options();
  }
  // The stepper keeps a reference to the system: a temporary would dangle, so it is refused.
  explicit Newton(const S&&, NewtonOptions = {}) = delete;
  Newton(const S&&, NewtonOptions, LinearStep) = delete;

  void set_observer(Observer* observer) { observer_ = observer; }

 private:
  void check_options() const {
    require_tolerance(options_.residual_tolerance, "residual tolerance");
    require_tolerance(options_.step_tolerance, "step tolerance");
    if (options_.max_iterations < 1) {
      throw std::invalid_argument("iteration limit must be at least 1, got " + std::to_string(options_.max_iterations));
    }
    if (options_.reuse_jacobian < 1) {
      throw std::invalid_argument("Jacobian reuse must be at least 1 (1 is Newton), got " +
                                  std::to_string(options_.reuse_jacobian));
    }
    if (options_.reuse_jacobian > 1 && !keeps_factors()) {
      throw std::invalid_argument("reusing the Jacobian needs a linear solver that keeps its factors (GEPP)");
    }
  }

  bool keeps_factors() const {
    if constexpr (!KeepsFactors<LinearStep, Vector<N>>) {
      return false;
    } else if constexpr (requires { linear_step_.keeps_factors(); }) {
      return linear_step_.keeps_factors();
    } else {
      return true;
    }
  }

 public:
  // Sets x = x0 and evaluates f(x0). Throws std::invalid_argument for a wrong size or non-finite x0.
  void start(const Vector<N>& x0) {
    const int n = system_.dimension();
    if (x0.size() != n) {
      throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                  std::to_string(n) + " unknowns");
    }
    linalg::require_finite(x0, "starting point");
    x_ = x0;
    f_.resize(n);
    J_.resize(n, n);
    dx_.setZero(n);
    trial_x_.resize(n);
    trial_f_.resize(n);
    result_ = NewtonCounts{};  // status: running
    forcing_.start();
    jacobian_fresh_ = false;
    stalled_inner_solves_ = 0;
    if (observer_ != nullptr) started_at_ = std::chrono::steady_clock::now();  // only traces need the time
    evaluate_at(x_, f_);
    residual_at_start_ = f_.template lpNorm<Eigen::Infinity>();
    running_ = true;
    stopped_ = false;
    if (!linalg::all_finite(f_)) {
      finish(StopReason::non_finite);
    } else if (residual_small(residual_at_start_, options_.residual_tolerance)) {
      finish(StopReason::residual_small);
    }
  }

  // One Newton iteration. Returns false once the iteration has ended.
  bool step() {
    if (!running_) return false;
    ++result_.iterations;

    // 1. The Jacobian at x (already there when the system evaluates f and J together); with
    //    reuse_jacobian = K, only at iterations 1, K+1, 2K+1, ... (the chord method).
    const bool refactor = (result_.iterations - 1) % options_.reuse_jacobian == 0;
    if (refactor) {
      if (!jacobian_fresh_) {
        system_.jacobian(x_, J_);
        ++result_.jacobian_evaluations;
      }
      if (!linalg::all_finite(J_)) return finish(StopReason::non_finite);
      ++result_.factorizations;
    }

    // 2. The Newton step: solve J dx = -f to relative residual eta_k, ||J dx + f|| <= eta_k ||f||
    //    (exactly, for a direct solver, which takes no eta_k); between refactorizations, with the
    //    factors of the last J kept.
    const double eta = forcing_for_step();
    const auto linear = refactor ? solve_for_step() : solve_with_kept_factors();
    if (linear.status == Status::singular) return finish(StopReason::singular_jacobian);
    if (linear.status == Status::non_finite || linear.status == Status::diverged || !linalg::all_finite(linear.x)) {
      return finish(StopReason::non_finite);
    }
    dx_ = linear.x;  // an iterative inner solve that hit its limit still gives a usable (inexact) step
    const bool capped = !std::isnan(eta) && linear.status == Status::max_iterations;  // short of eta_k

    // 3. Move: the full step; or, damped, x + lambda dx with the first lambda = 1, 1/2, 1/4, ... whose
    //    f is finite and passes Armijo's sufficient decrease on the merit ||f||_2^2 (c = armijo_constant):
    //    ||f(x + lambda dx)||_2^2 <= (1 - 2 c lambda) ||f(x)||_2^2. After max_halvings halvings: no_progress.
    double lambda = 1.0;
    if (options_.damped) {
      const double merit = f_.squaredNorm();
      int halvings = 0;
      while (true) {
        trial_x_ = x_ + lambda * dx_;
        evaluate_at(trial_x_, trial_f_);
        if (linalg::all_finite(trial_f_) && sufficient_decrease(trial_f_.squaredNorm(), merit, lambda)) break;
        if (++halvings > options_.max_halvings) return finish(StopReason::no_descent);
        lambda *= 0.5;
      }
      x_ = trial_x_;
      f_ = trial_f_;
    } else {
      x_ += dx_;
      evaluate_at(x_, f_);
    }
    result_.step_norm = lambda * dx_.template lpNorm<Eigen::Infinity>();
    const double residual_before = result_.iterations == 1 ? residual_at_start_ : result_.residual_norm;
    result_.residual_norm = f_.template lpNorm<Eigen::Infinity>();
    // A capped inner solve whose step cut ||f|| by less than 10% is a stalled one.
    stalled_inner_solves_ = capped && result_.residual_norm > 0.9 * residual_before ? stalled_inner_solves_ + 1 : 0;

    // 4. Stop tests, in order: finite, residual small, step small, diverged, iteration limit, stalled
    //    inner solves.
    if (!linalg::all_finite(x_) || !linalg::all_finite(f_)) {
      finish(StopReason::non_finite);
    } else if (residual_small(result_.residual_norm, options_.residual_tolerance)) {
      finish(StopReason::residual_small);
    } else if (step_small(result_.step_norm, x_.template lpNorm<Eigen::Infinity>(), options_.step_tolerance)) {
      finish(StopReason::step_small);  // stopped moving, yet ||f|| is not small
    } else if (diverged(result_.residual_norm, residual_at_start_, options_.divergence_factor)) {
      finish(StopReason::diverged);
    } else if (result_.iterations >= options_.max_iterations) {
      finish(StopReason::iteration_limit);
    } else if (options_.stop_on_failed_inner_step && capped && !(result_.residual_norm < residual_before)) {
      // the inner solver could not resolve J here (past an assembly limit J is nearly singular), and
      // the inexact step it gave made ||f|| no smaller: stop before spending the sweep limit again
      finish(StopReason::inner_step_failed);
    } else if (stalled_inner_solves_ >= max_stalled_inner_solves) {
      // three capped inner solves in a row that barely moved ||f||: stop rather than spend the whole
      // sweep limit again at every iteration
      finish(StopReason::inner_limit);
    }
    // After the tests: the observer sees the verdict (and may end the run here).
    if (notify(linear.status, linear.iterations, lambda, eta, refactor) == StepControl::stop) end_early();
    return running_;
  }

  NewtonResult<N> solve(const Vector<N>& x0) {
    start(x0);
    while (step()) {
    }
    return result();
  }

  NewtonResult<N> result() const {
    NewtonResult<N> result{result_, x_};
    result.residual_norm = f_.template lpNorm<Eigen::Infinity>();
    return result;
  }

  // State between iterations.
  bool running() const { return running_; }
  Status status() const { return result_.status; }  // running until the iteration has ended
  bool stopped() const { return stopped_; }
  int iterations() const { return result_.iterations; }
  const Vector<N>& x() const { return x_; }
  const Vector<N>& residual() const { return f_; }
  const Matrix<N>& jacobian() const { return J_; }
  const NewtonOptions& options() const { return options_; }
  LinearStep& linear_step() { return linear_step_; }

 private:
  // f(point), and J(point) too when the system shares the work (then J is fresh for the next step).
  void evaluate_at(const Vector<N>& point, Vector<N>& f) {
    ++result_.function_evaluations;
    if constexpr (SharesEvaluation<S>) {
      system_.residual_and_jacobian(point, f, J_);
      ++result_.jacobian_evaluations;
      jacobian_fresh_ = true;
    } else {
      system_.residual(point, f);
      jacobian_fresh_ = false;
    }
  }

  // eta_k, told to an iterative linear step; NaN when the step is exact (direct) or forcing is none.
  double forcing_for_step() {
    if constexpr (TakesForcingTerm<LinearStep>) {
      bool iterative = true;
      if constexpr (requires { linear_step_.iterative(); }) iterative = linear_step_.iterative();
      if (iterative && options_.forcing.kind != ForcingOptions::Kind::none) {
        const double eta = forcing_.next(f_.template lpNorm<Eigen::Infinity>(), options_.residual_tolerance);
        linear_step_.set_relative_residual_tolerance(eta);
        return eta;
      }
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  // J dx = -f by the linear step. J and f are finite here (checked above and after every
  // evaluation), so a step that offers a path without its own input screens takes it.
  linalg::LinearResult<N> solve_for_step() {
    if constexpr (requires { linear_step_.solve_prechecked(J_, f_); }) {
      return linear_step_.solve_prechecked(J_, -f_);
    } else {
      return linear_step_.solve(J_, -f_);
    }
  }

  // J_old dx = -f with the factors of the last J (the chord iterations; checked in check_options()).
  linalg::LinearResult<N> solve_with_kept_factors() {
    if constexpr (KeepsFactors<LinearStep, Vector<N>>) {
      return linear_step_.solve_with_factors(-f_);
    } else {
      throw std::logic_error("the linear step keeps no factors");
    }
  }

  bool finish(StopReason reason) {
    result_.status = status_of(reason);
    result_.reason = reason;
    running_ = false;
    return false;
  }

  // The observer said stop: the run ends here, before a verdict (status stays running).
  void end_early() {
    stopped_ = running_;
    running_ = false;
  }

  StepControl notify(Status linear_status, int linear_iterations, double lambda, double eta, bool refactored) {
    if (observer_ == nullptr) return StepControl::proceed;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
    const int jacobian = options_.reuse_jacobian > 1 ? int{refactored} : NewtonRecord::every_iteration;
    return observer_->on_step(*this, {result_.iterations, result_.residual_norm, f_.norm(), result_.step_norm,
                               linear_status, linear_iterations, lambda, elapsed, eta, jacobian});
  }

  const S& system_;
  NewtonOptions options_;
  LinearStep linear_step_;
  ForcingTerm forcing_;
  Observer* observer_ = nullptr;
  Vector<N> x_ = linalg::zero_or_empty<Vector<N>>(), f_ = linalg::zero_or_empty<Vector<N>>();
  Vector<N> dx_ = linalg::zero_or_empty<Vector<N>>(), trial_x_ = linalg::zero_or_empty<Vector<N>>();
  Vector<N> trial_f_ = linalg::zero_or_empty<Vector<N>>();
  Matrix<N> J_ = linalg::zero_or_empty<Matrix<N>>();
  NewtonCounts result_;
  double residual_at_start_ = 0.0;
  static constexpr int max_stalled_inner_solves = 3;
  int stalled_inner_solves_ = 0;  // capped inner solves in a row whose step cut ||f|| by less than 10%
  bool jacobian_fresh_ = false;
  bool running_ = false;
  bool stopped_ = false;
  std::chrono::steady_clock::time_point started_at_;
};

// Convenience: solve S from x0 with GEPP, or with the given linear step.
template <NonlinearSystem S>
NewtonResult<S::size> newton_solve(const S& system, const Vector<S::size>& x0, NewtonOptions options = {}) {
  return Newton<S>(system, options).solve(x0);
}

template <NonlinearSystem S, typename LinearStep>
NewtonResult<S::size> newton_solve(const S& system, const Vector<S::size>& x0, NewtonOptions options,
                                   LinearStep linear_step) {
  return Newton<S, LinearStep>(system, options, std::move(linear_step)).solve(x0);
}

std::string_view to_string(StopReason reason);
std::string termination_text(Status status, StopReason reason, int iterations, double residual_norm, double step_norm,
                             const NewtonOptions& options);

template <int N>
std::string termination_line(const NewtonResult<N>& result, const NewtonOptions& options) {
  return termination_text(result.status, result.reason, result.iterations, result.residual_norm, result.step_norm,
                          options);
}

}  // namespace numlab::nonlinear
