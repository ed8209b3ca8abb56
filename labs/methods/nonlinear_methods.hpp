#pragma once
// The nonlinear methods by their command-line names, run on one system from one start:
// "newton" (hand-written full Newton, with --linear and --damped), "dogleg" (the hand-written
// trust-region dogleg) and "gsl-<type>" for GSL's eight multiroot types.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

// newton, dogleg, gsl-hybrids, gsl-hybrid, gsl-dnewton, gsl-broyden, gsl-hybridsj, gsl-hybridj, gsl-newton, gsl-gnewton.
const std::vector<std::string>& nonlinear_method_names();

struct NonlinearSettings {
  nonlinear::NewtonOptions options;  // options.forcing: eta_k of an iterative inner solve (--forcing)
  nonlinear::LinearMethod linear = nonlinear::LinearMethod::gepp;  // newton's inner solver
};

// --forcing's names, for its help: none, constant:ETA, eisenstat-walker.
inline constexpr const char* forcing_choices = "none, constant:ETA (0 < ETA < 1) or eisenstat-walker";
// The forcing term named by --forcing. Throws std::invalid_argument naming what is wrong.
nonlinear::ForcingOptions forcing_named(const std::string& text);
struct NonlinearRun {
  Eigen::VectorXd x;
  Status status = Status::max_iterations;
  int iterations = 0;
  double residual_norm = 0.0;  // ||f||_inf
  double step_norm = 0.0;      // ||dx||_inf of the last step
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
  std::string termination;  // the closing "Termination: ..." line
  int factorizations = 0;   // linear solves with a new J (newton; fewer than iterations with --reuse-jacobian)
};

// Throws std::invalid_argument for an unknown method, a linear solver that does not fit, or a bad start.
NonlinearRun run_nonlinear_method(const std::string& method, const nonlinear::DynamicSystem& system,
                                  const Eigen::VectorXd& x0, const NonlinearSettings& settings,
                                  NewtonTraceObserver* observer = nullptr);

}  // namespace numlab::cli
