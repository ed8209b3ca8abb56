#pragma once
// GSL's multiroot solvers, the reference for numlab's Newton. This header and gsl_multiroot.cpp
// are the only place gsl_multiroot_* is called: callers pass a DynamicSystem and Eigen vectors.
//
// Derivative-free (f only): hybrids, hybrid, dnewton, broyden.
// With the Jacobian (f and J): hybridsj, hybridj, newton, gnewton.
//
// GslMultiroot is a stepper (numlab/solver.hpp), like numlab's Newton, and gives the same result
// type, NewtonResult:
//   start(x0)  gsl_multiroot_*solver_set, then the residual test at x0;
//   step()     one gsl_multiroot_*solver_iterate, then GSL's stop tests, in order:
//              GSL reported an error -> its status (the message kept in the result);
//              x not finite -> non_finite;
//              gsl_multiroot_test_residual(f, residual_tolerance) -> converged (residual_small);
//              gsl_multiroot_test_delta(dx, x, step_tolerance, step_tolerance) -> no_progress (step_small):
//                a small step is not a root, so only test_residual gives converged; for the hybrid
//                types (hybrids, hybrid, hybridsj, hybridj), trust-region methods whose one rejected
//                step may be tiny while the region is not, instead MINPACK's hybrj test on the
//                radius, delta <= step_tolerance ||D x||_2 -> no_progress (radius_small);
//              max_iterations reached -> max_iterations.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"
#include "numlab/solver.hpp"

namespace numlab::nonlinear {

// hybrids, hybrid, dnewton, broyden, hybridsj, hybridj, newton, gnewton.
const std::vector<std::string>& gsl_multiroot_types();

// A GSL solver of one type for one system, allocated once and reused by every start() (as numlab's
// Newton object is from pose to pose in a sweep). Only NewtonOptions' tolerances and iteration
// limit apply (GSL's types do their own damping, if any).
class GslMultiroot {
 public:
  using Observer = StepObserver<GslMultiroot, NewtonRecord>;

  // Throws std::invalid_argument for an unknown type, a tolerance that is negative or not finite,
  // an iteration limit below 1, or damping.
  GslMultiroot(const DynamicSystem& system, const std::string& type, NewtonOptions options = {});
  GslMultiroot(const DynamicSystem&&, const std::string&, NewtonOptions = {}) = delete;  // system must outlive it
  ~GslMultiroot();
  GslMultiroot(const GslMultiroot&) = delete;
  GslMultiroot& operator=(const GslMultiroot&) = delete;

  // The observer, if any, receives one record per iteration (its linear fields are not applicable).
  void set_observer(Observer* observer) { observer_ = observer; }

  // Throws std::invalid_argument for a wrong-sized or non-finite x0.
  void start(const Eigen::VectorXd& x0);
  // One GSL iteration and the stop tests. Returns false once the iteration has ended.
  bool step();
  NewtonResult<Eigen::Dynamic> solve(const Eigen::VectorXd& x0);
  NewtonResult<Eigen::Dynamic> result() const;

  bool running() const { return running_; }
  Status status() const { return counts_.status; }  // running until the iteration has ended
  bool stopped() const { return stopped_; }
  int iterations() const { return counts_.iterations; }
  const Eigen::VectorXd& x() const { return x_; }
  const NewtonOptions& options() const { return options_; }

 private:
  bool finish(StopReason reason);
  StepControl notify();

  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
  NewtonOptions options_;
  Observer* observer_ = nullptr;
  Eigen::VectorXd x_;
  NewtonCounts counts_;
  bool running_ = false;
  bool stopped_ = false;
};

// Solves system from x0 with GSL type `type` (one of gsl_multiroot_types()): a GslMultiroot's
// solve(). Throws std::invalid_argument for an unknown type, a wrong-sized or non-finite x0.
NewtonResult<Eigen::Dynamic> gsl_multiroot_solve(const DynamicSystem& system, const Eigen::VectorXd& x0,
                                                 const std::string& type, const NewtonOptions& options = {},
                                                 GslMultiroot::Observer* observer = nullptr);

}  // namespace numlab::nonlinear
