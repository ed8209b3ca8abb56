#pragma once
// The nonlinear methods by their command-line names, run on one system from one start:
// "newton" (hand-written full Newton, with --linear and --damped) and "gsl-<type>" for GSL's eight
// multiroot types.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::cli {

// newton, gsl-hybrids, gsl-hybrid, gsl-dnewton, gsl-broyden, gsl-hybridsj, gsl-hybridj, gsl-newton, gsl-gnewton.
const std::vector<std::string>& nonlinear_method_names();

struct NonlinearSettings {
  nonlinear::NewtonOptions options;
  std::string linear = "gepp";  // newton's inner solver
};

struct NonlinearRun {
  Eigen::VectorXd x;
  Status status = Status::max_iterations;
  int iterations = 0;
  double residual_inf = 0.0;
  double step_inf = 0.0;
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
  std::string termination;  // the closing "Termination: ..." line
};

// Throws std::invalid_argument for an unknown method or linear solver, or a bad start.
NonlinearRun run_nonlinear_method(const std::string& method, const nonlinear::DynamicSystem& system,
                                  const Eigen::VectorXd& x0, const NonlinearSettings& settings,
                                  nonlinear::NewtonObserver<Eigen::Dynamic>* observer = nullptr);

}  // namespace numlab::cli
