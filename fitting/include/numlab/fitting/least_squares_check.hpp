#pragma once
// The check behind a fit's status converged: what a least-squares fit with an intercept must
// satisfy, whatever method found it, up to rounding.
//
//  1. Its residual r = y - p(x), with p the reported coefficients in powers of x, is orthogonal to
//     the fit's columns (the normal equations V^T r = 0). The columns are taken as t^k,
//     t = (x - c) / s (scaled_basis.hpp): the same space as the x^k, and no power overflows.
//  2. Hence 0 <= R^2 <= 1 (the constant column is in the space: RSS <= TSS).
//
// The bound on |sum_i t_i^k r_i| is what rounding can explain: each method's backward error
// (the normal equations' |V|^T (|y| + |V||b|), or QR's per column), moved from the x^k to the t^k,
// where |x^j| weighs at most g_i^j, g_i = (|c| + |x_i|) / s; plus the error of evaluating p in
// powers of x, h_i = sum_j |p_j| |x_i|^j, and for normal-scaled of mapping q(t) to p(x),
// sum_j |a_j| g_i^j. So
//
//   |sum_i t_i^k r_i| <= gamma sum_i g_i^k (|y_i| + h_i + |r_i| + sum_j |a_j| g_i^j),
//   gamma = 10 m (D + 1) eps  (m points; a factor m of slack for the normwise backward errors).

#include <Eigen/Core>

#include "numlab/fitting/scaled_basis.hpp"

namespace numlab::fitting {

struct LeastSquaresCheck {
  bool finite = true;             // every coefficient and residual is finite
  bool orthogonal = true;         // 1 holds for every power
  int worst_power = 0;            // the power k with the largest ratio of |t_k^T r| to its bound
  double worst_ratio = 0.0;       // that ratio (<= 1 when 1 holds)
  bool r_squared_in_range = true; // 2 holds (NaN R^2, all y equal, is not a failure)
  bool passed() const { return finite && orthogonal && r_squared_in_range; }
};

// coefficients: p in powers of x. scaled_coefficients: q in powers of t when the method solved in
// t (normal-scaled), else empty. r_squared: the fit's R^2.
LeastSquaresCheck check_least_squares(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                      const Eigen::VectorXd& coefficients, const Eigen::VectorXd& scaled_coefficients,
                                      double r_squared);

}  // namespace numlab::fitting
