#pragma once
// One status vocabulary for every numlab method (see docs/architecture.md).
// A status is a result, not an exception: exceptions are for misuse and bad input.

#include <optional>
#include <string_view>

namespace numlab {

enum class Status {
  running,          // the stepper has not finished: no verdict yet
  converged,        // the method finished and its answer is usable
  max_iterations,   // the iteration limit was reached before the stop test passed
  singular,         // a pivot or determinant was zero relative to the matrix's scale
  non_finite,       // an infinity or NaN appeared during the iteration
  diverged,         // the iterates grew without bound
  no_progress,      // the iterates stopped improving
  cannot_assemble,  // a linkage cannot close at this input
};

constexpr std::string_view to_string(Status status) {
  switch (status) {
    case Status::running: return "running";
    case Status::converged: return "converged";
    case Status::max_iterations: return "max_iterations";
    case Status::singular: return "singular";
    case Status::non_finite: return "non_finite";
    case Status::diverged: return "diverged";
    case Status::no_progress: return "no_progress";
    case Status::cannot_assemble: return "cannot_assemble";
  }
  return "unknown";
}

}  // namespace numlab
