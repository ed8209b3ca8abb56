#pragma once
// What the linear exercises' detectors share (docs/exercises.md, "Diagnosis"): when a replayed
// wrong method explains a student's numbers better than numlab's reference does.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

namespace numlab::exercises::detectors {

// A hypothesis explains the student's numbers when it changes the answer (its replay lies farther
// than `allowed`, the check's tolerance, from numlab's answer: `separation`, finite) and the
// student's numbers lie within `tolerance` of the replay (its accuracy, from the conditioning), and
// at least a hundred times closer to it than it lies to numlab's answer, and agree with it to three
// digits at least (a replay whose conditioning or growth makes its own accuracy meaningless explains
// nothing: "your x equals its x to 1" is no evidence, however far numlab's answer lies).
inline constexpr double least_agreement = 1e-3;
inline bool explains(double to_hypothesis, double separation, double tolerance, double allowed) {
  if (!(separation > allowed) || !std::isfinite(separation)) return false;
  return to_hypothesis <= std::min({tolerance, 1e-2 * separation, least_agreement});
}

// ||x - y||_inf / ||y||_inf (absolute when y is 0); infinite when sizes differ or x is not finite.
double relative_distance(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y);

// "2.2e-16" (2 significant digits), as the checks' messages write a measured quantity.
std::string measured(double value);

}  // namespace numlab::exercises::detectors
