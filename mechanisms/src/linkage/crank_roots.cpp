#include "crank_roots.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms::crank_roots {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double brent(const std::function<double(double)>& f, double lo, double hi, int& most_iterations) {
  const double f_lo = f(lo), f_hi = f(hi);
  if (!std::isfinite(f_lo) || !std::isfinite(f_hi)) return nan;
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) == (f_hi < 0.0)) return nan;  // no sign change (it did not survive the polish): no root
  gsl_set_error_handler_off();  // GSL's default handler aborts; a failure is a NaN here
  gsl_function F;
  F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  F.params = const_cast<std::function<double(double)>*>(&f);
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double root = nan;
  if (gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS) {
    for (int k = 1; k <= 200; ++k) {
      if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
      if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 1e-10, 0.0) == GSL_SUCCESS) {
        root = gsl_root_fsolver_root(s);
        most_iterations = std::max(most_iterations, k);
        break;
      }
    }
  }
  gsl_root_fsolver_free(s);
  return root;
}

std::vector<double> half_turn_roots(const std::function<double(double)>& g, double from, double flat, int& iterations) {
  std::vector<double> roots;
  for (const double lo : {from, from + pi}) {
    const double g_lo = g(lo), g_hi = g(lo + pi);
    // 1. A bracket: strictly opposite signs, neither end a tangency.
    if (std::abs(g_lo) <= flat || std::abs(g_hi) <= flat || (g_lo < 0.0) == (g_hi < 0.0)) continue;
    // 2. Brent inside it.
    const double root = brent(g, lo, lo + pi, iterations);
    if (std::isfinite(root)) roots.push_back(root);
  }
  return roots;
}

Eigen::VectorXd polished_pose(const LinkageSolver& solver, double t, const Eigen::VectorXd& q0) {
  const LinkageModel& model = solver.model();
  Eigen::VectorXd q = solver.solve(t, q0).q, f;
  Eigen::MatrixXd J;
  for (int k = 0; k < 3; ++k) {
    model.residual(q, t, f);
    model.jacobian(q, t, J);
    q -= Eigen::PartialPivLU<Eigen::MatrixXd>(J).solve(f);
  }
  return q;
}

double output_rate_at(const LinkageModel& model, const LinkageOutput& output, const std::vector<LinkLine>& lines,
                      double t, const Eigen::VectorXd& q) {
  return output_rate(output, lines, joint_motions(model, q, linkage_velocity(model, t, q), Eigen::VectorXd()));
}

std::vector<RateRoot> rate_roots_over_sweep(const LinkageSolver& solver, const LinkageOutput& output, double from,
                                            double to, int& iterations, double& reached) {
  const LinkageModel& model = solver.model();
  const std::vector<LinkLine> lines = link_lines(model.description());
  std::vector<RateRoot> roots;
  reached = from;
  // 1. The sweep.
  const LinkageSweep sweep = linkage_sweep(solver, from, to, to > from ? 1.0 : -1.0);
  const LinkagePose* previous = nullptr;
  double previous_rate = nan;
  for (const LinkagePose& pose : sweep.poses) {
    if (pose.outcome.status != Status::converged || pose.velocity.size() == 0) break;
    reached = pose.driver;
    const double value = output_rate(output, lines, joint_motions(model, pose.q, pose.velocity, Eigen::VectorXd()));
    if (!std::isfinite(value)) continue;  // no rate here (a singular pose): the bracket spans it
    // 2. A sign change between two poses is a bracket; 3. Brent in it.
    if (previous != nullptr && (previous_rate < 0.0) != (value < 0.0)) {
      const Eigen::VectorXd start = previous->q;
      const auto rate = [&](double x) { return output_rate_at(model, output, lines, x, polished_pose(solver, x, start)); };
      const double t0 = model.driver_from_user(previous->driver), t1 = model.driver_from_user(pose.driver);
      const double root = brent(rate, std::min(t0, t1), std::max(t0, t1), iterations);
      if (std::isfinite(root)) roots.push_back({model.driver_to_user(root), polished_pose(solver, root, start)});
    }
    previous = &pose, previous_rate = value;
  }
  return roots;
}

}  // namespace numlab::mechanisms::crank_roots
