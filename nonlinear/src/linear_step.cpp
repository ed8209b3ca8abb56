#include "numlab/nonlinear/linear_step.hpp"

#include <algorithm>
#include <stdexcept>

namespace numlab::nonlinear {

const std::vector<std::string>& newton_linear_methods() {
  static const std::vector<std::string> names = {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu", "inverse2x2"};
  return names;
}

RuntimeLinearStep::RuntimeLinearStep(const std::string& method, int n, linalg::GaussSeidelOptions gauss_seidel)
    : method_(method), gauss_seidel_(gauss_seidel) {
  const auto& names = newton_linear_methods();
  if (std::find(names.begin(), names.end(), method) == names.end()) {
    throw std::invalid_argument("unknown linear method '" + method +
                                "' (expected gepp, gauss-seidel, gsl-lu, eigen-lu or inverse2x2)");
  }
  if (method == "inverse2x2" && n != 2) {
    throw std::invalid_argument("inverse2x2 needs a 2x2 system, but this one has " + std::to_string(n) + " unknowns");
  }
}

linalg::LinearResult<Eigen::Dynamic> RuntimeLinearStep::solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& rhs) {
  if (method_ == "gepp") return gepp_.solve(J, rhs);
  if (method_ == "gauss-seidel") return gauss_seidel_.solve(J, rhs);
  if (method_ == "gsl-lu") return gsl_lu_.solve(J, rhs);
  if (method_ == "eigen-lu") return eigen_lu_.solve(J, rhs);
  // inverse2x2: the closed form on the 2x2 system.
  const linalg::LinearResult<2> fixed = linalg::solve2x2(J, rhs);
  linalg::LinearResult<Eigen::Dynamic> result;
  result.x = fixed.x;
  result.status = fixed.status;
  result.iterations = fixed.iterations;
  result.residual_norm = fixed.residual_norm;
  return result;
}

}  // namespace numlab::nonlinear
