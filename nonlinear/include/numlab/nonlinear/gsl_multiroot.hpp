#pragma once
// GSL's multiroot solvers, the reference for numlab's Newton. This header and gsl_multiroot.cpp
// are the only place gsl_multiroot_* is called: callers pass a DynamicSystem and Eigen vectors.
//
// Derivative-free (f only): hybrids, hybrid, dnewton, broyden.
// With the Jacobian (f and J): hybridsj, hybridj, newton, gnewton.
// Stop tests mirror numlab's Newton: gsl_multiroot_test_residual(f, residual_tolerance), or
// gsl_multiroot_test_delta(dx, x, step_tolerance, step_tolerance).

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

// hybrids, hybrid, dnewton, broyden, hybridsj, hybridj, newton, gnewton.
const std::vector<std::string>& gsl_multiroot_types();

struct GslMultirootResult {
  Eigen::VectorXd x;
  Status status = Status::max_iterations;
  int iterations = 0;
  double residual_norm = 0.0;  // ||f(x)||_inf
  double step_norm = 0.0;      // ||dx||_inf of the last iteration
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
  std::string gsl_message;  // GSL's own words when an iteration reported an error
};

// A GSL solver of one type for one system, allocated once and reused by every solve (as numlab's
// Newton object is from pose to pose in a sweep). Throws std::invalid_argument for an unknown type.
class GslMultiroot {
 public:
  GslMultiroot(const DynamicSystem& system, const std::string& type);
  ~GslMultiroot();
  GslMultiroot(const GslMultiroot&) = delete;
  GslMultiroot& operator=(const GslMultiroot&) = delete;
  // As gsl_multiroot_solve() below, with this solver.
  GslMultirootResult solve(const Eigen::VectorXd& x0, const NewtonOptions& options = {},
                           NewtonObserver<Eigen::Dynamic>* observer = nullptr);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// Solves system from x0 with GSL type `type` (one of gsl_multiroot_types()). The observer, if
// any, receives one record per iteration (its linear fields are not applicable).
// Throws std::invalid_argument for an unknown type, a wrong-sized or non-finite x0.
GslMultirootResult gsl_multiroot_solve(const DynamicSystem& system, const Eigen::VectorXd& x0, const std::string& type,
                                       const NewtonOptions& options = {},
                                       NewtonObserver<Eigen::Dynamic>* observer = nullptr);

}  // namespace numlab::nonlinear
