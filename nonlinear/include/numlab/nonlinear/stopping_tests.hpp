#pragma once
// Newton's stopping tests, each a named function (as GSL keeps gsl_multiroot_test_residual and
// gsl_multiroot_test_delta apart from its iterate functions). Newton and the dyad stepper both
// call these, so the tests are written once.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace numlab::nonlinear {

// A tolerance must be a finite number >= 0: infinity would pass every test at once (a "root" after
// no iteration), NaN none. Misuse: std::invalid_argument naming the tolerance.
inline void require_tolerance(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string(what) + " must be a finite number >= 0, got " + std::to_string(value));
  }
}

// Residual small: ||f(x)||_inf <= tolerance. The only test that says x is a root.
inline bool residual_small(double residual_norm, double tolerance) { return residual_norm <= tolerance; }

// Step small: ||dx||_inf <= tolerance (1 + ||x||_inf). The iterates have stopped moving; that is
// not a root (a small step is not a root). Alone it ends the iteration as no_progress.
inline bool step_small(double step_norm, double x_norm, double tolerance) {
  return step_norm <= tolerance * (1.0 + x_norm);
}

// Diverged: ||f||_inf has grown past `factor` times its start (or times 1, for a start near a root).
inline bool diverged(double residual_norm, double residual_at_start, double factor) {
  return residual_norm > factor * std::max(residual_at_start, 1.0);
}

// Sufficient decrease (Armijo) for damped Newton on the merit m(x) = ||f(x)||_2^2. Along the Newton
// direction the merit's slope at lambda = 0 is -2 m(x), so Armijo's condition
//   m(x + lambda dx) <= m(x) + c * lambda * slope
// reads m(trial) <= (1 - 2 c lambda) m(x), with the customary constant c = 1e-4.
inline constexpr double armijo_constant = 1e-4;

inline bool sufficient_decrease(double trial_merit, double merit, double lambda) {
  return trial_merit <= (1.0 - 2.0 * armijo_constant * lambda) * merit;
}

}  // namespace numlab::nonlinear
