#pragma once
// The change of variable behind `normal-scaled`: t = (x - c) / s, with c the middle of the x range
// and s its half-width, so t fills [-1, 1]. On [-1, 1] the powers 1, t, ..., t^D are far from
// parallel (they are near-parallel on [0, 20] or [1e5, 2e5]), so V^T V is well conditioned.

#include <Eigen/Core>

namespace numlab::fitting {

struct AffineScaling {
  double centre = 0.0;  // c
  double scale = 1.0;   // s > 0
};

// c and s for the data's x range; s = 1 when every x is the same.
AffineScaling scaling_for(const Eigen::VectorXd& x);

// t_i = (x_i - c) / s.
Eigen::VectorXd to_scaled(const Eigen::VectorXd& x, const AffineScaling& scaling);

// The coefficients of p(x) = q((x - c) / s), given q's coefficients a0 ... aD: an exact algebraic
// identity, evaluated by Horner's rule on polynomials in x (p = a_D; p = p * (x - c)/s + a_k).
// Scalar is double, or long double for the extended-precision reference.
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> to_original_powers(const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& a,
                                                          Scalar centre, Scalar scale) {
  const Eigen::Index size = a.size();
  // t = (x - c) / s = u0 + u1 x.
  const Scalar u0 = -centre / scale;
  const Scalar u1 = Scalar(1) / scale;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> p = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Zero(size);
  p(0) = a(size - 1);
  for (Eigen::Index k = size - 2; k >= 0; --k) {
    // p <- p * (u0 + u1 x): p has degree D-1-k before this step.
    for (Eigen::Index j = size - 1 - k; j >= 1; --j) p(j) = p(j) * u0 + p(j - 1) * u1;
    p(0) = p(0) * u0;
    // p <- p + a_k.
    p(0) += a(k);
  }
  return p;
}

inline Eigen::VectorXd to_original_powers(const Eigen::VectorXd& scaled_coefficients, const AffineScaling& scaling) {
  return to_original_powers<double>(scaled_coefficients, scaling.centre, scaling.scale);
}

}  // namespace numlab::fitting
