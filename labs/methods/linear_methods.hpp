#pragma once
// The linear methods by their command-line names, run on one system A x = b.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/inverse2x2.hpp"

namespace numlab::cli {

using DynamicResult = linalg::LinearResult<Eigen::Dynamic>;

struct LinearSettings {
  std::optional<double> tolerance;    // gauss-seidel: stop tolerance; gepp: relative pivot tolerance
  std::optional<int> max_iterations;  // gauss-seidel: sweep limit
};

// Observers that receive the steps of the hand-written methods (any may be null).
struct LinearTracers {
  linalg::GaussElimination<Eigen::Dynamic>::Observer* elimination = nullptr;
  linalg::GaussSeidel<Eigen::Dynamic>::Observer* sweeps = nullptr;
  linalg::ClosedForm2x2::Observer* closed_form = nullptr;
};

// gepp, gepp-no-pivot, gauss-seidel, gauss-seidel-plain, inverse2x2, gsl-lu, gsl-qr, eigen-lu.
const std::vector<std::string>& linear_method_names();

// One line saying what a method is.
std::string describe_linear_method(const std::string& method);

// Runs `method`; throws std::invalid_argument for an unknown method or a size it cannot take.
DynamicResult run_linear_method(const std::string& method, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                const LinearSettings& settings = {}, LinearTracers tracers = {});

}  // namespace numlab::cli
