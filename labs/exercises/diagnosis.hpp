#pragma once
// What went wrong, named (docs/exercises.md, "Diagnosis"). A failing check tests hypotheses about
// the cause against the evidence it holds (the student's replies beside numlab's): each hypothesis
// is a Detector. The check keeps the most specific detector that fires; the results keep the most
// specific diagnosis over all failing checks, and the reports lead with it.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace numlab::exercises {

// How specific a cause is. A detector that names the exact mistake outranks one that names a
// family of mistakes, which outranks a symptom.
enum class Specificity {
  symptom = 1,   // "the residual is not the one after the step": true, but not yet the cause
  family = 2,    // "J is not the derivative of f": a class of mistakes
  exact = 3,     // "your sweep equals a Jacobi sweep to 1e-16": one mistake, matched by the numbers
  forbidden = 4  // "called numpy.linalg.solve": breaks a stated rule, whatever the numbers say
};

struct Diagnosis {
  std::string cause;  // a stable id, e.g. "jacobi_sweep" (docs/exercises.md lists them)
  Specificity specificity = Specificity::symptom;
  // The evidence and the remedy in one sentence a student can act on: "your sweep 1 equals a
  // Jacobi sweep to 1e-16: x_i must use the x_j already updated in this sweep".
  std::string evidence;
};

// One hypothesis: `test` returns the evidence when it holds, nothing when it does not.
struct Detector {
  std::string cause;
  Specificity specificity = Specificity::symptom;
  std::function<std::optional<std::string>()> test;
};

// The most specific detector that fires (the first listed among equals), or nothing.
std::optional<Diagnosis> diagnose(const std::vector<Detector>& detectors);

// The more specific of two diagnoses (the first among equals); nothing only when both are nothing.
std::optional<Diagnosis> more_specific(const std::optional<Diagnosis>& first, const std::optional<Diagnosis>& second);

}  // namespace numlab::exercises
