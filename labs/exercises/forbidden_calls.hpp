#pragma once
// The library functions each exercise forbids (docs/exercises.md, "Library calls"), by language.
// TASK.md states each list; numlab watches Python and Octave programs for calls to them
// (call_watch.hpp), and the rule check fails when one was called (call_rule.hpp).

#include <string>
#include <vector>

namespace numlab::exercises {

struct ForbiddenCalls {
  // The rule as TASK.md states it, quoted in the rule check's message: "Use arrays for storage
  // only: no library solver, LU or inverse."
  std::string rule;
  // What the exercise asks instead, for the diagnosis: "this exercise asks for elimination by hand".
  std::string asks;
  // Python: "MODULE:ATTRIBUTE" ("numpy.linalg:solve", "numpy.polynomial:Polynomial.fit"), shown as
  // MODULE.ATTRIBUTE. Octave: function names ("inv", "polyfit").
  std::vector<std::string> python;
  std::vector<std::string> octave;

  bool empty() const { return python.empty() && octave.empty(); }
};

// The forbidden calls of the exercise called `exercise`; an empty list for one that forbids none.
const ForbiddenCalls& forbidden_calls(const std::string& exercise);

// "numpy.linalg:solve" -> "numpy.linalg.solve".
std::string python_call_name(const std::string& entry);

}  // namespace numlab::exercises
