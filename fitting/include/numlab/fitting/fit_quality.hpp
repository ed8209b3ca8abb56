#pragma once
// What a fit's numbers are worth: residual statistics, and the warning when the condition of the
// matrix a method solved leaves too few digits to trust.

#include <Eigen/Core>
#include <string>

namespace numlab::fitting {

struct FitStatistics {
  double residual_sd = 0.0;  // sqrt(RSS / (n - D - 1)), 0 when n = D + 1 (an interpolant)
  double r_squared = 0.0;    // 1 - RSS / TSS, TSS = sum (y - mean y)^2; NaN (undefined) when TSS = 0
};

FitStatistics fit_statistics(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& coefficients);

// Digits a solve with condition number kappa may lose: about log10(kappa) of the 16 in a double.
// Empty when kappa * eps < 1e-3 (13 or more digits survive); otherwise a sentence saying how many
// digits are left, or that none are (kappa * eps >= 0.5).
std::string conditioning_warning(double condition_estimate, const std::string& matrix_name);

}  // namespace numlab::fitting
