#include "exercises/diagnosis.hpp"

namespace numlab::exercises {

std::optional<Diagnosis> diagnose(const std::vector<Detector>& detectors) {
  std::optional<Diagnosis> best;
  for (const Detector& detector : detectors) {
    if (best && detector.specificity <= best->specificity) continue;  // cannot outrank what fired
    if (std::optional<std::string> evidence = detector.test()) {
      best = Diagnosis{detector.cause, detector.specificity, std::move(*evidence)};
    }
  }
  return best;
}

std::optional<Diagnosis> more_specific(const std::optional<Diagnosis>& first, const std::optional<Diagnosis>& second) {
  if (!second) return first;
  if (!first) return second;
  return second->specificity > first->specificity ? second : first;
}

}  // namespace numlab::exercises
