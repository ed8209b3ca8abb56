#include "methods/nonlinear_methods.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "parsing/argument_parsing.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/nonlinear/linear_step.hpp"

namespace numlab::cli {

namespace {

std::string gsl_termination(const nonlinear::NewtonResult<Eigen::Dynamic>& result,
                            const nonlinear::NewtonOptions& options) {
  std::string word(to_string(result.status));
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::toupper(c); });
  std::string reason = result.message.empty() ? "" : "GSL: " + std::string(result.message) + "; ";
  if (result.status == Status::max_iterations) reason += fmt::format("limit {}; ", options.max_iterations);
  return fmt::format("Termination: {} ({}||f||_inf = {:.3g}, last ||dx||_inf = {:.3g}, after {} iterations)", word,
                     reason, result.residual_norm, result.step_norm, result.iterations);
}

}  // namespace

const std::vector<std::string>& nonlinear_method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"newton", "dogleg"};
    for (const std::string& type : nonlinear::gsl_multiroot_types()) all.push_back("gsl-" + type);
    return all;
  }();
  return names;
}

nonlinear::ForcingOptions forcing_named(const std::string& text) {
  using Kind = nonlinear::ForcingOptions::Kind;
  nonlinear::ForcingOptions forcing;
  if (text == "none") {
    forcing.kind = Kind::none;
  } else if (text == "eisenstat-walker") {
    forcing.kind = Kind::eisenstat_walker;
  } else if (text.starts_with("constant:")) {
    forcing.kind = Kind::constant;
    const std::string eta = text.substr(9);
    try {
      forcing.eta = parse_finite_number(eta);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(fmt::format("--forcing constant:ETA: {}", error.what()));
    }
    if (!(forcing.eta > 0.0 && forcing.eta < 1.0)) {
      throw std::invalid_argument(
          fmt::format("--forcing constant:ETA: ETA must be in (0, 1), got {}", linalg::quoted_token(eta)));
    }
  } else {
    throw std::invalid_argument(fmt::format("--forcing {}: expected {}", linalg::quoted_token(text), forcing_choices));
  }
  return forcing;
}

NonlinearRun run_nonlinear_method(const std::string& method, const nonlinear::DynamicSystem& system,
                                  const Eigen::VectorXd& x0, const NonlinearSettings& settings,
                                  NewtonTraceObserver* observer) {
  // Newton and GSL give the same result type; only the termination line is written differently.
  auto run_of = [](const nonlinear::NewtonResult<Eigen::Dynamic>& result, std::string termination) {
    return NonlinearRun{result.x,          result.status,
                        result.iterations, result.residual_norm,
                        result.step_norm,  result.function_evaluations,
                        result.jacobian_evaluations, std::move(termination), result.factorizations};
  };
  if (method == "newton") {
    const nonlinear::DynamicReference reference{system};
    DynamicNewton newton(reference, settings.options,
                         nonlinear::RuntimeLinearStep(settings.linear, system.dimension(),
                                                      nonlinear::inner_gauss_seidel_options(settings.options.forcing)));
    newton.set_observer(observer);
    newton.start(x0);
    while (newton.step()) {  // one Newton iteration
    }
    const auto result = newton.result();
    return run_of(result, nonlinear::termination_line(result, settings.options));
  }
  if (method == "dogleg") {
    nonlinear::Dogleg dogleg(system, settings.options);
    dogleg.set_observer(observer);
    dogleg.start(x0);
    while (dogleg.step()) {  // one trust-region iteration
    }
    const auto result = dogleg.result();
    return run_of(result, nonlinear::termination_line(result, settings.options));
  }
  if (method.starts_with("gsl-")) {
    nonlinear::GslMultiroot gsl(system, method.substr(4), settings.options);
    gsl.set_observer(observer);
    gsl.start(x0);
    while (gsl.step()) {  // one iteration of GSL's method
    }
    const auto result = gsl.result();
    return run_of(result, gsl_termination(result, settings.options));
  }
  throw std::invalid_argument("unknown nonlinear method '" + method + "'");
}

}  // namespace numlab::cli
