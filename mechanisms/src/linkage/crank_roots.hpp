#pragma once
// The root finding of --analyse (crank_analysis.cpp): GSL's Brent solver on a bracket, the roots of
// a function monotone on each half of a turn (the driver's toggles), and the roots of an output's
// velocity ratio over a sweep of the crank (the output's toggles, any crank-driven model).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::mechanisms::crank_roots {

// Brent's method (gsl_root_fsolver_brent) on f over [lo, hi], where f(lo) and f(hi) have opposite
// signs, to 1e-10 in x; NaN when they do not, or Brent fails. `most_iterations` keeps the largest count.
double brent(const std::function<double(double)>& f, double lo, double hi, int& most_iterations);

// The roots of g over the turn [from, from + 2 pi] when g is monotone on each half-turn
// [from, from + pi] and [from + pi, from + 2 pi]: each half is a bracket when g has strictly
// opposite signs at its ends, |g| > flat at both (an end within `flat` of zero is a tangency, a
// change point the crank passes: no root).
std::vector<double> half_turn_roots(const std::function<double(double)>& g, double from, double flat, int& iterations);

// A crank pose at t (radians): solved from q0, then three Newton steps with dense LU, to rounding.
Eigen::VectorXd polished_pose(const LinkageSolver& solver, double t, const Eigen::VectorXd& q0);

// The output's rate d(output)/d(crank) at the pose q, crank t (radians).
double output_rate_at(const LinkageModel& model, const LinkageOutput& output, const std::vector<LinkLine>& lines,
                      double t, const Eigen::VectorXd& q);

// A root of the output's rate: the crank there (user degrees, unwrapped) and the pose.
struct RateRoot {
  double crank_deg = 0.0;
  Eigen::VectorXd q;
};

// The roots of the output's rate along the sweep from `from` to `to` (user degrees, 1-degree steps):
//   1. sweep the crank, each pose solved from the one before (linkage_sweep);
//   2. a bracket wherever the rate (from the sweep's velocities) changes sign between two poses;
//   3. Brent on the rate at poses solved from the bracket's first pose and polished to rounding.
// The sweep ends at the first pose that fails. `reached` is the last crank value solved.
std::vector<RateRoot> rate_roots_over_sweep(const LinkageSolver& solver, const LinkageOutput& output, double from,
                                            double to, int& iterations, double& reached);

}  // namespace numlab::mechanisms::crank_roots
