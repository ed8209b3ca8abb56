#pragma once
// The unstable ways to a least-squares polynomial fit that the polyfit task rules out, replayed on a
// request (docs/exercises.md, "Diagnosis"): what each loses on these data is measured, not bounded,
// and compared with what the student's coefficients lose.

#include <Eigen/Core>

namespace numlab::exercises::detectors {

// An SVD of the Vandermonde matrix with its columns as they are (GSL's Golub-Reinsch
// gsl_linalg_SV_decomp, a bidiagonalising SVD like LAPACK's): numpy.linalg.lstsq(V, y) without the
// column scaling. Empty when there are fewer points than coefficients.
Eigen::VectorXd unscaled_svd_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

// The normal equations V^T V b = V^T y formed from power sums of the unscaled x and solved by GEPP
// (seed 001's method, numlab's fit --method normal). Empty when the solve fails.
Eigen::VectorXd power_sum_normal_fit(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

}  // namespace numlab::exercises::detectors
