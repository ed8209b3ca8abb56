#include "numlab/fitting/degree_sweep.hpp"

#include <cmath>

#include "numlab/fitting/log_relative_error.hpp"
#include "numlab/fitting/reference_fits.hpp"

namespace numlab::fitting {

std::vector<DegreeSweepRow> fit_degree_sweep(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int max_degree) {
  std::vector<DegreeSweepRow> rows;
  for (int degree = 1; degree <= max_degree; ++degree) {
    const Eigen::VectorXd reference = extended_precision_fit(x, y, degree);
    for (FitMethod method : {FitMethod::normal, FitMethod::normal_scaled, FitMethod::gsl, FitMethod::eigen_qr}) {
      FitOptions options;
      options.method = method;
      options.degree = degree;
      const PolynomialFit fit = fit_polynomial(x, y, options);
      const bool has_fit = fit.coefficients.size() > 0;
      rows.push_back({std::string(to_string(method)), degree,
                      has_fit ? weighted_coefficient_digits(fit.coefficients, reference, x) : 0.0,
                      has_fit ? fit.residual_sd : std::nan(""), fit.condition_estimate, fit.status,
                      !fit.warning.empty()});
    }
  }
  return rows;
}

}  // namespace numlab::fitting
