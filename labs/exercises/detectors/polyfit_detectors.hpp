#pragma once
// The polyfit exercise's detectors (docs/exercises.md, "Diagnosis"): the known wrong fits are
// replayed on the request (the reversed powers, the fit of another degree, the fit in a centred or
// scaled variable not mapped back, c and s also solved from the coefficients, the interpolant of
// the first or last D+1 points, normal equations with a wrong power sum, the scaled columns' fit
// not divided by the scales) and named
// when they explain the student's coefficients; an error no replay explains is compared with what
// an SVD of the unscaled V and the power-sum normal equations lose on the same data (unstable_fits).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "exercises/diagnosis.hpp"

namespace numlab::exercises::detectors {

struct PolyfitProblem {
  Eigen::VectorXd x, y;
  int degree = 1;
  Eigen::VectorXd expected;  // the reference's coefficients, lowest power first
  double allowed = 0.0;      // the check's tolerance on the column-weighted relative error
};

// `coefficients`: the student's, of any count (degree + 1 is the right one).
std::optional<Diagnosis> diagnose_polyfit(const PolyfitProblem& problem, const Eigen::VectorXd& coefficients);

// Coefficients sent for a fit with fewer distinct x than degree + 1.
Diagnosis undetermined_fit(std::size_t points, std::size_t distinct, int degree);

}  // namespace numlab::exercises::detectors
