#pragma once
// The one solver contract. Every method numlab writes by hand is a stepper with the same names, so
// a lab, a trace printer or a student's loop drives any of them the same way (GSL's
// alloc / set / iterate / test, with the caller owning the loop):
//
//   Options     a plain struct with documented defaults, given to the constructor;
//   start(...)  loads the problem (and checks it: bad input throws std::invalid_argument);
//   step()      performs exactly one step (a pivot column, a sweep, a Newton iteration, a pose)
//               and returns whether the stepper is still running;
//   solve(...)  start(), then step() until it returns false, then the Result;
//   running()   true from start() until the last step;
//   status()    Status::running until then, afterwards the verdict (numlab/status.hpp): no
//               stepper says `converged` before it has finished;
//   iterations() the method's own count so far: the steps taken, except GEPP (pivot columns
//               eliminated: n of its 2n steps) and the crank sweeps (poses solved); the table
//               "What iterations() counts" in docs/architecture.md, held by tests/contract;
//   x()         the current iterate (or solution);
//   stopped()   true when the observer ended the run early (below); status() then stays running:
//               the run ended before the method reached a verdict;
//   an observer whose on_step(const Stepper&, const Record&) is called after every step, attached
//               with set_observer(); null by default, so an untraced solve pays nothing. It returns
//               a StepControl: proceed, or stop, which ends the run there (step() returns false),
//               as Ceres' callbacks do. A caller that wants to stop between steps of its own loop
//               simply stops calling step().
//
// The concept below checks the names; tests/contract checks every stepper against it.

#include <concepts>

#include "numlab/status.hpp"

namespace numlab {

template <typename S>
concept Stepper = requires(S& stepper, const S& state) {
  { stepper.step() } -> std::same_as<bool>;
  { state.running() } -> std::same_as<bool>;
  { state.status() } -> std::same_as<Status>;
  { state.iterations() } -> std::convertible_to<int>;
  { state.stopped() } -> std::same_as<bool>;
  state.x();
};

// What an observer returns after each step: go on, or end the run at this step.
enum class StepControl { proceed, stop };

// What an observer of stepper S with records R implements.
template <typename S, typename R>
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual StepControl on_step(const S& stepper, const R& record) = 0;
};

}  // namespace numlab
