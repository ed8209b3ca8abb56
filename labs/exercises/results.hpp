#pragma once
// What `numlab exercise check` reports (docs/exercises.md, "Output"): the results of a battery as
// results.json (the Exercism test-runner interface, version 3), as text for the terminal, and as
// a self-contained report.html in the style of the lab reports.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"

namespace numlab::exercises {

// {"version": 3, "status", "message", "diagnosis", "diagnosis_cause", "tests": [{"name", "status", "message", "task_id", "output",
// "timing"}]}. The status is "pass" when every check passes, "error" when every check errored (or
// none ran), "fail" otherwise. The top message is null unless the status is "error": then it says
// why (`error_message` when given, else the first check's error). A test's message is null on a
// pass, else the check's message with its diagnosis ("Diagnosis: ...") or, when no detector fired,
// its hint ("Hint: ..."); "diagnosis" is the run's most specific diagnosis (its evidence) and
// "diagnosis_cause" its id, both null when no detector fired; its output is the program's stderr
// (null when empty); "timing" (an extra field) holds seconds per request: "you" and each reference.
// "variant" is the variant's ID (variant.hpp), null without one.
nlohmann::ordered_json results_json(const std::vector<CheckResult>& results, const std::string& error_message = "",
                                    const Variant& variant = Variant());

// First the run's diagnosis ("Diagnosis: ...") when a detector fired. When a check does not pass,
// then "Fix first: CHECK — its message's first line" (and "Replay it:
// COMMAND" when the result has a replay); then one line per check ("✓ name", "✗ name", "✗ name
// (error)") with the time per request beside the references', then the failures (message, hint,
// shortened output, replay command), then the summary line ("5 of 9 checks pass; 3 fail, 1 error").
// With a variant, the title line names it ("numlab exercise gepp (variant s1234567): ...").
std::string results_text(const Exercise& exercise, const std::vector<CheckResult>& results,
                         const Variant& variant = Variant());

// The summary line alone.
std::string results_summary(const std::vector<CheckResult>& results);

// report.html: the failure to fix first (as in the text), the exercise, the command checked, a table
// of the checks and each failure in full with its replay command.
std::string results_html(const Exercise& exercise, const std::vector<CheckResult>& results,
                         const std::string& command, const Variant& variant = Variant());

}  // namespace numlab::exercises
