#pragma once
// Detectors for a student's Newton on a linkage closure (issue 29 §1; docs/exercises.md,
// "Diagnosis"): each tests one hypothesis against the failing reply. Most replay the student's
// suspected loop with numlab's f and J (x <- x - dx, the residual recorded before the step, J
// transposed, finite differences with a given step, the seed's start) and compare its trace with
// the student's; the others read the reply (angles that did not move, a stop test that fits the
// residual's signs, an iteration count past the limit). Written for any closure through a
// ClosureEvaluator; jansen-newton and mustang-newton call them from newton_battery.hpp.

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exercises/detectors/mechanism_jacobian.hpp"
#include "exercises/diagnosis.hpp"
#include "exercises/linkage_checks.hpp"

namespace numlab::exercises {

// numlab's closure with one slip in it, and what the slip is ("the bend 20 deg used as 20 rad").
struct SlippedClosure {
  std::string what;
  ClosureEvaluator evaluate;
};

struct NewtonEvidence {
  // The request.
  double driver = 0.0;
  Eigen::VectorXd start;
  double tolerance = 1e-10;
  long long max_iterations = 20;
  // The reply.
  Eigen::VectorXd x;
  std::string status;
  long long iterations = 0;
  std::optional<std::vector<TraceRow>> trace;
  // numlab's.
  ClosureEvaluator evaluate;
  Eigen::VectorXd seed_start;         // the seed's own guess (restart_from_seed_guess)
  std::optional<Eigen::VectorXd> exact;  // the pose the request should reach, when it has one
  double rounding = 0.0;              // what re-evaluating f adds (1e3 eps L)
  double links_sum = 1.0;             // L, f's scale
  std::function<std::string(int)> angle_name;
  // numlab's iteration count from this start where the task's stop rule decides it beyond
  // rounding (decided_iterations in linkage_checks.hpp), else nothing.
  std::optional<long long> decided_iterations;
  // The closure with a constant angle of the mechanism typed in degrees and used as radians (the
  // Mustang's bend pi/9 as 20): worlds a student's Newton may be solving.
  std::vector<SlippedClosure> constant_angle_slips;
};

// One Newton iteration loop as a student may have written it: numlab's f and J, and one mistake.
struct NewtonLoop {
  bool minus_step = false;     // x <- x - dx
  bool record_before = false;  // the trace's residual is ||f|| before the step
  bool never_update = false;   // x <- x + dx computed but never stored
  // The J used in place of the analytic one (nothing: the analytic J).
  std::function<Eigen::MatrixXd(const Eigen::VectorXd& x, const Eigen::MatrixXd& J)> jacobian;
};

// The trace of `loop` from `start` (the stop test max |f_i| <= tolerance, at most max_iterations).
std::vector<TraceRow> simulate_newton(const ClosureEvaluator& evaluate, double driver, const Eigen::VectorXd& start,
                                      double tolerance, long long max_iterations, const NewtonLoop& loop,
                                      Eigen::VectorXd* end = nullptr);

// The ranked detectors of a Newton reply's causes: the most specific that fires, or nothing.
std::vector<Detector> newton_detectors(const NewtonEvidence& evidence);
std::optional<Diagnosis> diagnose_newton(const NewtonEvidence& evidence);

}  // namespace numlab::exercises
