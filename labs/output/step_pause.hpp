#pragma once
// --step: the pause after each shown step. With stdin a terminal it waits for Enter (go on) or for
// q + Enter or the end of input (stop). Without a terminal it never waits, so scripts and CI never
// block: the first pause prints one note on stderr instead. A pause is what a program's observer
// returns to the stepper it watches (numlab/solver.hpp's StepControl).

#include "numlab/solver.hpp"

namespace numlab::cli {

class StepPause {
 public:
  explicit StepPause(bool enabled) : enabled_(enabled) {}

  // Waits (when enabled and stdin is a terminal) and returns the user's answer. Once stop has been
  // answered it returns stop at once, without asking again.
  StepControl after_step();
  bool stopped() const { return stopped_; }
  bool enabled() const { return enabled_; }
  // Seconds spent waiting for the user so far: timings leave them out.
  double seconds_waited() const { return seconds_waited_; }

 private:
  bool enabled_;
  bool stopped_ = false;
  double seconds_waited_ = 0.0;
};

}  // namespace numlab::cli
