#pragma once
// DIR/trace.html of `numlab exercise check --out DIR` (docs/exercises.md, "Your trace beside
// numlab's"): for a failing trace check, the student's steps and numlab's side by side, stepping
// together (first, previous, next, last, a slider, the arrow keys), the first step where they part
// highlighted with its sentence. One self-contained page: styles and script inline
// (labs/exercises/html/), the traces embedded as JSON; with scripts off it is the two traces as a
// static table with the parting row marked.

#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"

namespace numlab::exercises {

// The first check among `results` that failed with a trace beside numlab's, or null (then no page).
const CheckResult* failing_trace_check(const std::vector<CheckResult>& results);

// The page for `result` (a failing check that carries a trace comparison).
std::string trace_page_html(const Exercise& exercise, const CheckResult& result, const Variant& variant = Variant());

}  // namespace numlab::exercises
