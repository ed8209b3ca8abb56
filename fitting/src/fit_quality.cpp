#include "numlab/fitting/fit_quality.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "numlab/fitting/polynomial_fit.hpp"

namespace numlab::fitting {

FitStatistics fit_statistics(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& coefficients) {
  const Eigen::Index n = x.size();
  const Eigen::Index parameters = coefficients.size();
  double rss = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = y(i) - evaluate_polynomial(coefficients, x(i));
    rss += r * r;
  }
  const double tss = (y.array() - y.mean()).square().sum();
  FitStatistics statistics;
  statistics.residual_sd = n > parameters ? std::sqrt(rss / static_cast<double>(n - parameters)) : 0.0;
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
