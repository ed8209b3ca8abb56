#pragma once
// --trace and --step for the crank sweeps (`numlab mechanism jansen|jansen10|mustang`): one
// observer for both sweep steppers. It keeps every pose attempt (for JSON's "trace" and the
// tables printed afterwards), prints each one as it happens when given a stream, and with --step
// pauses after each one (only when stdin is a terminal).

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <ostream>

#include "commands/common_options.hpp"
#include "output/step_pause.hpp"
#include "numlab/mechanisms/sweep_observer.hpp"
#include "output/table.hpp"

namespace numlab::cli {

template <typename Sweep>
class CrankSweepTracer final : public mechanisms::SweepRecorder<Sweep> {
 public:
  CrankSweepTracer(std::ostream* rows, StepPause* pause) : rows_(rows), pause_(pause) {}

  StepControl on_step(const Sweep& sweep, const mechanisms::SweepPoseRecord& record) override {
    if (pause_ != nullptr && pause_->stopped()) return StepControl::stop;
    mechanisms::SweepRecorder<Sweep>::on_step(sweep, record);
    if (rows_ != nullptr) {
      if (this->attempts().size() == 1) {
        *rows_ << fmt::format("{:>12}  {:>10}  {:>10}  {:>10}  {:<15}  {}\n", "crank (deg)", "step", "iterations",
                              "||f||_inf", "status", "kept");
      }
      *rows_ << fmt::format("{:>12.5f}  {:>+10.5f}  {:>10}  {:>10}  {:<15}  {}\n", record.crank_deg, record.step_deg,
                            record.outcome.iterations, scientific(record.outcome.residual_norm),
                            to_string(record.outcome.status), record.accepted ? "yes" : "no");
    }
    return pause_ != nullptr ? pause_->after_step() : StepControl::proceed;
  }

 private:
  std::ostream* rows_;
  StepPause* pause_;
};

// One attempt as JSON; `extra` (e.g. the Mustang's condition and margin) goes before "accepted".
inline nlohmann::ordered_json attempt_json(const mechanisms::SweepAttempt& attempt,
                                           const nlohmann::ordered_json& extra = nlohmann::ordered_json::object()) {
  nlohmann::ordered_json entry = {{"crank_deg", attempt.crank_deg},
                                  {"step_deg", attempt.step_deg},
                                  {"iterations", attempt.outcome.iterations},
                                  {"residual_inf", number_or_null(attempt.outcome.residual_norm)},
                                  {"status", std::string(to_string(attempt.outcome.status))}};
  for (const auto& [key, value] : extra.items()) entry[key] = value;
  entry["accepted"] = attempt.accepted;
  return entry;
}

}  // namespace numlab::cli
