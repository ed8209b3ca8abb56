#pragma once
// Forcing terms of inexact Newton (Dembo, Eisenstat & Steihaug, SIAM J. Numer. Anal. 19(2), 1982).
//
// An iterative inner solver need not solve J dx = -f exactly. The step only has to satisfy
//     ||J dx + f|| <= eta_k ||f||,     0 <= eta_k < 1,
// and Newton still converges locally: linearly when eta_k <= eta_max < 1, superlinearly when
// eta_k -> 0, quadratically when eta_k = O(||f||). Too small an eta_k far from the root wastes inner
// sweeps ("oversolving"); too large an eta_k near it costs outer iterations. Here ||.|| is ||.||_inf,
// the norm of Newton's residual test. A direct solver (GEPP, LU, the 2x2 closed form) solves
// exactly and takes no eta_k.
//
// The choices (ForcingOptions::kind):
//   none              the inner solver's own stop test decides (Gauss-Seidel: its update tolerance);
//                     no eta_k. Kept to show what it does: the step is never more accurate than that
//                     absolute tolerance, and Newton can stall above its own.
//   constant          eta_k = eta.
//   eisenstat_walker  Eisenstat & Walker's Choice 2 (SIAM J. Sci. Comput. 17(1), 1996, 16-32):
//       eta_0 = eta_initial,   eta_k = gamma (||f_k|| / ||f_{k-1}||)^alpha
//     with the safeguards, in this order:
//       a. if gamma eta_{k-1}^alpha > 0.1:  eta_k = max(eta_k, gamma eta_{k-1}^alpha)
//          (Eisenstat & Walker: eta may not fall much faster than it did; one lucky residual drop
//          does not buy an expensive inner solve)
//       b. eta_k = min(eta_k, eta_max)
//       c. eta_k = max(eta_k, 0.5 tol / ||f_k||), still at most eta_max (Kelley, Iterative Methods
//          for Linear and Nonlinear Equations, SIAM 1995, eq. 6.20): the last step need only bring
//          ||f|| to about half the residual tolerance, not below it.
//
// ForcingTerm holds the two numbers Choice 2 remembers (||f_{k-1}||, eta_{k-1}); no heap.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace numlab::nonlinear {

struct ForcingOptions {
  enum class Kind { none, constant, eisenstat_walker };
  Kind kind = Kind::eisenstat_walker;
  double eta = 0.1;          // constant's eta
  double eta_initial = 0.5;  // Choice 2's eta_0 (Eisenstat & Walker's)
  double gamma = 0.9;        // Choice 2's gamma and alpha (their recommended pair)
  double alpha = 2.0;
  double eta_max = 0.9;      // safeguard b
};

// Throws std::invalid_argument naming the first option out of range.
inline void require_valid(const ForcingOptions& options) {
  auto require_in = [](double value, double low, double high, bool high_included, const char* what) {
    if (!(value > low && (value < high || (high_included && value == high)))) {
      throw std::invalid_argument(std::string("forcing term: ") + what + " must be in (" + std::to_string(low) + ", " +
                                  std::to_string(high) + (high_included ? "]" : ")") + ", got " +
                                  std::to_string(value));
    }
  };
  require_in(options.eta, 0.0, 1.0, false, "eta");
  require_in(options.eta_initial, 0.0, 1.0, false, "eta_0");
  require_in(options.gamma, 0.0, 1.0, true, "gamma");
  require_in(options.alpha, 1.0, 2.0, true, "alpha");
  require_in(options.eta_max, 0.0, 1.0, false, "eta_max");
}

class ForcingTerm {
 public:
  explicit ForcingTerm(ForcingOptions options = {}) : options_(options) { require_valid(options_); }

  // A new Newton run: the next eta is eta_0.
  void start() { previous_residual_ = previous_eta_ = std::numeric_limits<double>::quiet_NaN(); }

  // eta_k for the step from x_k, where ||f_k||_inf = residual_norm; tolerance: Newton's residual
  // tolerance (safeguard c). NaN for Kind::none.
  double next(double residual_norm, double tolerance) {
    double eta = std::numeric_limits<double>::quiet_NaN();
    switch (options_.kind) {
      case ForcingOptions::Kind::none: return eta;
      case ForcingOptions::Kind::constant: eta = options_.eta; break;
      case ForcingOptions::Kind::eisenstat_walker: eta = eisenstat_walker(residual_norm, tolerance); break;
    }
    previous_residual_ = residual_norm;
    previous_eta_ = eta;
    return eta;
  }

  const ForcingOptions& options() const { return options_; }

 private:
  double eisenstat_walker(double residual_norm, double tolerance) const {
    if (std::isnan(previous_eta_)) return options_.eta_initial;  // k = 0
    double eta = options_.gamma * std::pow(residual_norm / previous_residual_, options_.alpha);
    const double floor = options_.gamma * std::pow(previous_eta_, options_.alpha);
    if (floor > 0.1) eta = std::max(eta, floor);                                  // a.
    eta = std::min(eta, options_.eta_max);                                        // b.
    return std::min(options_.eta_max, std::max(eta, 0.5 * tolerance / residual_norm));  // c.
  }

  ForcingOptions options_;
  double previous_residual_ = std::numeric_limits<double>::quiet_NaN();
  double previous_eta_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace numlab::nonlinear
