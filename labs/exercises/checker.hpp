#pragma once
// Runs an exercise's battery through a session and turns each check's outcome into a result:
// pass, fail (the program answered, wrongly, or said it could not), or error (no proper reply).

#include <optional>
#include <string>
#include <vector>

#include "exercises/exercise.hpp"
#include "exercises/session.hpp"

namespace numlab::exercises {

enum class CheckStatus { pass, fail, error };

std::string to_string(CheckStatus status);  // "pass", "fail", "error"

// One request of a check and what came of it, for the replay file (replay.hpp).
struct Exchange {
  nlohmann::json request;  // as sent: the check's fields, "exercise" and "id" (counted from 1 in each check)
  nlohmann::json reply;    // the program's reply; null when none came or it replied with an error
  std::string error;       // the program's "error", or why no reply came; "" otherwise
  Expectation expected;    // what the check expected (empty when it said nothing)
};

struct CheckResult {
  std::string name;
  int task_id = 1;
  CheckStatus status = CheckStatus::error;
  std::string message;  // "" on pass
  std::string hint;     // a known mistake that fits, or ""
  std::string output;   // the program's stderr during the check
  double seconds_per_request = 0.0;  // the student's program
  std::vector<ReferenceTime> references;
  std::vector<Exchange> exchanges;  // the check's requests, in order
  std::string replay;  // the command that replays a failure (set by `exercise check --out`), or ""
  std::optional<Diagnosis> diagnosis;  // the detector that explained the failure, if one fired
  std::optional<TraceComparison> trace{};  // a failing trace check's traces side by side (trace.html)
};

// The diagnosis of a whole run: the most specific over the checks that did not pass (the first
// among equals), or nothing when no detector fired.
std::optional<Diagnosis> overall_diagnosis(const std::vector<CheckResult>& results);

// What to tell the student about one failed check after its message: "Diagnosis: ..." when a
// detector fired, else "Hint: ..." when a generic hint fits, else "".
std::string explanation(const CheckResult& result);

// After this many checks in a row end in ChildFailure, the rest are not run: each is an error that
// says so (a program that hangs on every request costs at most this many time limits).
inline constexpr int max_failures_in_a_row = 3;

// The battery of `variant` (variant.hpp; without one, the checks as they always were).
std::vector<CheckResult> run_checks(const Exercise& exercise, Session& session, const Variant& variant = Variant());

// One check of `exercise` alone (what `exercise replay` runs), its requests recorded.
CheckResult run_check(const Exercise& exercise, const Check& check, Session& session);

}  // namespace numlab::exercises
