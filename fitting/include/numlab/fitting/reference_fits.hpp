#pragma once
// The fits numlab's hand-written normal equations are checked against.

#include <Eigen/Core>

namespace numlab::fitting {

// The Vandermonde matrix: row i is 1, x_i, ..., x_i^D.
Eigen::MatrixXd vandermonde(const Eigen::VectorXd& x, int degree);

// kappa_2 = sigma_max / sigma_min (Eigen's JacobiSVD); infinite when sigma_min is 0.
double two_norm_condition(const Eigen::MatrixXd& A);

// A with each column divided by its 2-norm (zero columns left as they are).
Eigen::MatrixXd unit_columns(const Eigen::MatrixXd& A);

struct ReferenceFit {
  Eigen::VectorXd coefficients;
  double condition_estimate = 0.0;  // kappa_2 of V with unit-norm columns
  double condition_unscaled = 0.0;  // kappa_2 of V itself
  bool rank_deficient = false;
};

// gsl_multifit_linear: SVD of V after GSL scales its columns to unit norm. condition_estimate is
// 1 / gsl_multifit_linear_rcond (of that column-scaled V). GSL's error handler is off here.
// condition_unscaled comes from an Eigen SVD of V.
ReferenceFit gsl_multifit_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

// Eigen's HouseholderQR of V; both condition numbers from Eigen's JacobiSVD.
ReferenceFit eigen_qr_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

// An accuracy reference for charts and tests where NIST certifies nothing: Householder QR in long
// double (64-bit significand) on the scaled variable t (see scaled_basis.hpp), mapped back in long
// double. Checked against NIST's certified values in the tests.
Eigen::VectorXd extended_precision_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

}  // namespace numlab::fitting
