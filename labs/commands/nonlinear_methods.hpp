#pragma once
// The nonlinear methods by their command-line names, run on one system from one start:
// "newton" (hand-written full Newton, with --linear and --damped) and "gsl-<type>" for GSL's eight
// multiroot types.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

// newton, gsl-hybrids, gsl-hybrid, gsl-dnewton, gsl-broyden, gsl-hybridsj, gsl-hybridj, gsl-newton, gsl-gnewton.
const std::vector<std::string>& nonlinear_method_names();

struct NonlinearSettings {
  nonlinear::NewtonOptions options;  // options.forcing: eta_k of an iterative inner solve (--forcing)
  nonlinear::LinearMethod linear = nonlinear::LinearMethod::gepp;  // newton's inner solver
};

// --forcing's names, for its help: none, constant:ETA, eisenstat-walker.
inline constexpr const char* forcing_choices = "none, constant:ETA (0 < ETA < 1) or eisenstat-walker";
// The forcing term named by --forcing. Throws std::invalid_argument naming what is wrong.
nonlinear::ForcingOptions forcing_named(const std::string& text);
// settings.options.forcing from --forcing: the default (Eisenstat-Walker) when not given. Given, it
// must apply (require_applies: --method newton with an iterative --linear, gauss-seidel).
nonlinear::ForcingOptions forcing_option(const std::optional<std::string>& text, bool is_newton,
                                         nonlinear::LinearMethod linear);
// settings.options.reuse_jacobian from --reuse-jacobian K: 1 (Newton) when not given. Given, K must
// be at least 1 and apply (--method newton with --linear gepp, the solver that keeps its factors).
int reuse_jacobian_option(std::optional<int> every, bool is_newton, nonlinear::LinearMethod linear);

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
