#pragma once
// The log relative error (LRE) NIST's StRD reports are judged by: the number of correct significant
// digits of a computed value q against a certified value c,
//   LRE = -log10(|q - c| / |c|)   (c != 0),      LRE = -log10(|q|)   (c == 0),
// clipped to [0, 15] (15 digits is all a certified value carries; an exact match also counts 15).

#include <Eigen/Core>

namespace numlab::fitting {

constexpr double max_lre = 15.0;

double log_relative_error(double computed, double certified);

// The smallest LRE over the coefficients: the digits every coefficient has. 0 when sizes differ
// or a value is not finite.
double min_log_relative_error(const Eigen::VectorXd& computed, const Eigen::VectorXd& certified);

// Digits of a whole coefficient vector, for comparisons where some reference coefficients are
// near zero (their own LRE would say 0 digits however small the error is): each coefficient is
// weighted by the size of its term on the data, w_k = max_i |x_i|^k, and
//   digits = -log10( max_k w_k |b_k - r_k| / max_k w_k |r_k| ),  clipped to [0, 15].
double weighted_coefficient_digits(const Eigen::VectorXd& computed, const Eigen::VectorXd& reference,
                                   const Eigen::VectorXd& x);

}  // namespace numlab::fitting
