#pragma once
// The rule "uses no forbidden library function" (docs/exercises.md, "Library calls"), checked by
// run_checks for every exercise whose list (forbidden_calls.hpp) is not empty: the calls the
// session's watch noticed are taken after each check. After the battery, each failing check during
// which a forbidden function was called is diagnosed `library_call` with the calls of the whole
// run, and one more check, the rule itself, passes or fails. That check is added only when the
// program was watched (Python or Octave), and then when a forbidden call was noticed or some check
// passed: a program that got nothing right (a starter, a crash) has not yet shown a rule kept.

#include <optional>
#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "exercises/forbidden_calls.hpp"
#include "exercises/library_calls.hpp"

namespace numlab::exercises {

inline constexpr const char* call_rule_check_name = "uses no forbidden library function (TASK.md rule)";

class CallRule {
 public:
  explicit CallRule(const std::string& exercise) : calls_(forbidden_calls(exercise)) {}

  // After a check, the last of `results`: the calls made during it, taken from `session`.
  void after_check(Session& session, const std::vector<CheckResult>& results);

  // After the battery: the failing checks that called a forbidden function diagnosed, and the
  // rule's own check appended (not when the exercise forbids nothing, the program was not watched,
  // or it called nothing forbidden and passed no check).
  void finish(std::vector<CheckResult>& results) const;

 private:
  const ForbiddenCalls& calls_;
  LibraryCalls noticed_;
  std::vector<std::size_t> calling_checks_;  // the indices in `results` of the checks that called one
};

// "called numpy.linalg.solve 12 times and numpy.linalg.inv once: this exercise asks for elimination
// by hand"; nothing when no call was noticed.
std::optional<Diagnosis> library_call_diagnosis(const LibraryCalls& calls, const ForbiddenCalls& forbidden);

}  // namespace numlab::exercises
