#include "numlab/fitting/log_relative_error.hpp"

#include <algorithm>
#include <cmath>

namespace numlab::fitting {

double log_relative_error(double computed, double certified) {
  if (!std::isfinite(computed)) return 0.0;
  const double error = certified != 0.0 ? std::abs(computed - certified) / std::abs(certified) : std::abs(computed);
  if (error == 0.0) return max_lre;
  return std::clamp(-std::log10(error), 0.0, max_lre);
}

double min_log_relative_error(const Eigen::VectorXd& computed, const Eigen::VectorXd& certified) {
  if (computed.size() != certified.size() || computed.size() == 0) return 0.0;
  double digits = max_lre;
  for (Eigen::Index k = 0; k < computed.size(); ++k) {
    digits = std::min(digits, log_relative_error(computed(k), certified(k)));
  }
  return digits;
}

double weighted_coefficient_digits(const Eigen::VectorXd& computed, const Eigen::VectorXd& reference,
                                   const Eigen::VectorXd& x) {
  if (computed.size() != reference.size() || computed.size() == 0 || !computed.allFinite()) return 0.0;
  const double largest_x = x.cwiseAbs().maxCoeff();
  double error = 0.0, size = 0.0, weight = 1.0;  // weight = largest_x^k
  for (Eigen::Index k = 0; k < computed.size(); ++k, weight *= largest_x) {
    error = std::max(error, weight * std::abs(computed(k) - reference(k)));
    size = std::max(size, weight * std::abs(reference(k)));
  }
  if (error == 0.0) return max_lre;
  if (size == 0.0) return 0.0;
  return std::clamp(-std::log10(error / size), 0.0, max_lre);
}

}  // namespace numlab::fitting
