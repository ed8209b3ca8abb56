#include <cctype>
#include <cstdio>
#include <string>

#include "numlab/nonlinear/newton.hpp"

namespace numlab::nonlinear {

std::string_view to_string(StopReason reason) {
  switch (reason) {
    case StopReason::running: return "running";
    case StopReason::residual_small: return "residual below tolerance";
    case StopReason::step_small: return "step below tolerance";
    case StopReason::iteration_limit: return "iteration limit reached";
    case StopReason::singular_jacobian: return "the Jacobian is singular";
    case StopReason::non_finite: return "a value is no longer finite";
    case StopReason::diverged: return "the residual grew without bound";
    case StopReason::no_descent: return "damping found no step that decreases ||f||";
    case StopReason::no_progress: return "the iteration is making no progress";
    case StopReason::radius_small: return "the trust region's radius fell below the step tolerance (delta <= tol ||D x||_2)";
    case StopReason::inner_step_failed: return "an inner solve reached its sweep limit short of eta_k, and its step did not decrease ||f||";
    case StopReason::inner_limit: return "three inner solves in a row reached their sweep limit short of eta_k, each step cutting ||f|| by under 10%";
  }
  return "unknown";
}

namespace {
std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}
}  // namespace

std::string termination_text(Status status, StopReason reason, int iterations, double residual_norm, double step_norm,
                             const NewtonOptions& options) {
  std::string word(numlab::to_string(status));
  for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::string detail;
  switch (reason) {
    case StopReason::residual_small:
      detail = "||f||_inf = " + format_number(residual_norm) + " <= " + format_number(options.residual_tolerance);
      break;
    case StopReason::step_small:
      detail = "||dx||_inf = " + format_number(step_norm) + " <= " + format_number(options.step_tolerance) +
               " (1 + ||x||); ||f||_inf = " + format_number(residual_norm);
      break;
    case StopReason::iteration_limit:
      detail = "limit " + std::to_string(options.max_iterations) + "; ||f||_inf = " + format_number(residual_norm) +
               ", last ||dx||_inf = " + format_number(step_norm);
      break;
    case StopReason::diverged:
      detail = "||f||_inf = " + format_number(residual_norm);
      break;
    default:
      detail = std::string(to_string(reason)) + "; ||f||_inf = " + format_number(residual_norm);
      break;
  }
  if (reason == StopReason::iteration_limit || reason == StopReason::diverged || reason == StopReason::residual_small ||
      reason == StopReason::step_small) {
    detail = std::string(to_string(reason)) + ": " + detail;
  }
  return "Termination: " + word + " (" + detail + ", after " + std::to_string(iterations) + " iterations)";
}

}  // namespace numlab::nonlinear
