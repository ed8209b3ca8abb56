#pragma once
// The inverse2x2 exercise's detectors (docs/exercises.md, "Diagnosis"): the known wrong closed
// forms (transposed, the determinant's sign, the adjugate not divided by det), the unscaled
// determinant that under- or overflows, and the singular thresholds, each tested on the numbers.

#include <Eigen/Core>
#include <optional>

#include "exercises/diagnosis.hpp"

namespace numlab::exercises::detectors {

// The student's reply to the inverse of A: "singular", or an inverse.
struct InverseAnswer {
  bool singular = false;
  std::optional<Eigen::Matrix2d> inverse;
};

std::optional<Diagnosis> diagnose_inverse2x2(const Eigen::Matrix2d& A, const InverseAnswer& answer);

}  // namespace numlab::exercises::detectors
