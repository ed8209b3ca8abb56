#include "numlab/fitting/fit_quality.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "numlab/fitting/polynomial_fit.hpp"

namespace numlab::fitting {

namespace {

// A power of two near max |y| (1 when every y is 0): dividing by it is exact, and leaves values
// whose squares do not overflow even when y is near the largest doubles.
double scale_of(const Eigen::VectorXd& y) {
  const double largest = y.cwiseAbs().maxCoeff();
  return largest > 0.0 && std::isfinite(largest) ? std::ldexp(1.0, std::ilogb(largest)) : 1.0;
}

}  // namespace

// The sums are of y / s and r / s (s = scale_of(y)): with y = 1e300 the squares of y and r would
// overflow to inf, and R^2 = 1 - inf / inf would be NaN. The scaling is by a power of two, so for
// ordinary data the statistics are the same to the last bit.
FitStatistics fit_statistics(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& coefficients) {
  const Eigen::Index n = x.size();
  const Eigen::Index parameters = coefficients.size();
  const double s = scale_of(y);
  double rss = 0.0;  // of r / s
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = y(i) / s - evaluate_polynomial(coefficients, x(i)) / s;
    rss += r * r;
  }
  const Eigen::ArrayXd scaled = y.array() / s;
  const double tss = (scaled - scaled.mean()).square().sum();  // of y / s
  FitStatistics statistics;
  statistics.residual_sd = n > parameters ? s * std::sqrt(rss / static_cast<double>(n - parameters)) : 0.0;
  statistics.r_squared = tss > 0.0 ? 1.0 - rss / tss : std::numeric_limits<double>::quiet_NaN();
  return statistics;
}

std::string conditioning_warning(double condition_estimate, const std::string& matrix_name) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  if (!(condition_estimate * eps >= 1e-3)) return "";
  std::ostringstream text;
  text.precision(2);
  text << "The " << matrix_name << " has condition number " << condition_estimate << " (kappa * eps = "
       << condition_estimate * eps << ")";
  if (condition_estimate * eps >= 0.5) {
    text << ": the coefficients may have no correct digits. Use normal-scaled, gsl or eigen-qr.";
  } else {
    const double digits_left = -std::log10(condition_estimate * eps);
    text << ": expect only about " << static_cast<int>(std::lround(digits_left))
         << " correct digits in the coefficients, fewer in the smallest ones.";
  }
  return text.str();
}

}  // namespace numlab::fitting
