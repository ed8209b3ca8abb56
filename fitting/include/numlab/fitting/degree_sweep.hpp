#pragma once
// The degree sweep: every fit method at degrees 1 .. max_degree, judged against the
// extended-precision reference (reference_fits.hpp). The `fit` lab and `numlab bench fit` read it.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/fitting/polynomial_fit.hpp"

namespace numlab::fitting {

struct DegreeSweepRow {
  std::string method;        // normal, normal-scaled, gsl, eigen-qr
  int degree;
  double digits;             // weighted_coefficient_digits against the reference; 0 without coefficients
  double residual_sd;        // NaN without coefficients
  double condition;          // the fit's condition_estimate
  Status status;
  bool warned;               // the fit carries a warning
};

// The four methods (normal with GEPP) at each degree.
std::vector<DegreeSweepRow> fit_degree_sweep(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int max_degree);

}  // namespace numlab::fitting
