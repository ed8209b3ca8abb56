#pragma once
// The normal equations of a polynomial fit, seed 001's curve_fit for any degree:
//
//   [ n        sum x     ...  sum x^D     ] [b0]   [ sum y     ]
//   [ sum x    sum x^2   ...  sum x^D+1   ] [b1] = [ sum x y   ]
//   [ ...                                 ] [..]   [ ...       ]
//   [ sum x^D  sum x^D+1 ...  sum x^2D    ] [bD]   [ sum x^D y ]
//
// that is (V^T V) b = V^T y for the Vandermonde matrix V with rows 1, x_i, ..., x_i^D. Forming
// V^T V squares V's condition number: the root cause of the digits the plain method loses.

#include <Eigen/Core>

namespace numlab::fitting {

struct NormalEquations {
  Eigen::MatrixXd matrix;  // (D+1) x (D+1) power sums
  Eigen::VectorXd rhs;     // D+1 moment sums
};

NormalEquations build_normal_equations(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

}  // namespace numlab::fitting
