#pragma once
// Why an iteration stopped, and the one function that turns the reason into a status.
// docs/architecture.md's table "StopReason -> Status" is tested against status_of().

#include <array>

#include "numlab/status.hpp"

namespace numlab::nonlinear {

// residual_small is the only reason with status converged; step_small and radius_small end with
// status no_progress. no_progress: GSL's adapter only, when GSL reports that its iteration is not
// making progress. New reasons go last, and into stop_reasons below.
enum class StopReason {
  running, residual_small, step_small, iteration_limit, singular_jacobian, non_finite, diverged, no_descent, no_progress,
  inner_limit,  // three inner solves in a row reached their sweep limit short of eta_k, and ||f|| barely fell
  inner_step_failed,  // with stop_on_failed_inner_step: an inner solve reached its sweep limit short of eta_k
                      // and its step did not decrease ||f||
  radius_small  // GSL's hybrid types only: the trust region's radius fell below step_tolerance ||D x||_2
};

inline constexpr std::array stop_reasons{
    StopReason::running,     StopReason::residual_small, StopReason::step_small,  StopReason::iteration_limit,
    StopReason::singular_jacobian, StopReason::non_finite, StopReason::diverged, StopReason::no_descent,
    StopReason::no_progress, StopReason::inner_limit,    StopReason::inner_step_failed, StopReason::radius_small};
static_assert(static_cast<std::size_t>(StopReason::radius_small) + 1 == stop_reasons.size(), "list every reason");

// The status an iteration that stopped for `reason` ends with: the one mapping from reason to
// status, used by Newton, the dogleg and GSL's adapter alike.
constexpr Status status_of(StopReason reason) {
  switch (reason) {
    case StopReason::running: return Status::running;
    case StopReason::residual_small: return Status::converged;  // the only test that says x is a root
    case StopReason::step_small: return Status::no_progress;    // stopped moving: a small step is not a root
    case StopReason::iteration_limit: return Status::max_iterations;
    case StopReason::singular_jacobian: return Status::singular;
    case StopReason::non_finite: return Status::non_finite;
    case StopReason::diverged: return Status::diverged;
    case StopReason::no_descent: return Status::no_progress;
    case StopReason::no_progress: return Status::no_progress;
    case StopReason::inner_limit: return Status::max_iterations;
    case StopReason::inner_step_failed: return Status::max_iterations;
    case StopReason::radius_small: return Status::no_progress;
  }
  return Status::running;
}

}  // namespace numlab::nonlinear
