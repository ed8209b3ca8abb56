#include "numlab/nonlinear/linear_step.hpp"

#include <algorithm>
#include <stdexcept>

namespace numlab::nonlinear {

const std::vector<std::string>& newton_linear_methods() {
  static const std::vector<std::string> names = {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu", "inverse2x2"};
  return names;
}

LinearMethod linear_method_named(const std::string& name) {
  const auto& names = newton_linear_methods();
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) {
    throw std::invalid_argument("unknown linear method '" + name +
                                "' (expected gepp, gauss-seidel, gsl-lu, eigen-lu or inverse2x2)");
  }
  return static_cast<LinearMethod>(found - names.begin());
}

std::string_view to_string(LinearMethod method) { return newton_linear_methods()[static_cast<std::size_t>(method)]; }

RuntimeLinearStep::RuntimeLinearStep(LinearMethod method, int n, linalg::GaussSeidelOptions gauss_seidel)
    : method_(method), gauss_seidel_(gauss_seidel) {
  if (method == LinearMethod::inverse2x2 && n != 2) {
    throw std::invalid_argument("inverse2x2 needs a 2x2 system, but this one has " + std::to_string(n) + " unknowns");
  }
}

RuntimeLinearStep::RuntimeLinearStep(const std::string& method, int n, linalg::GaussSeidelOptions gauss_seidel)
    : RuntimeLinearStep(linear_method_named(method), n, gauss_seidel) {}

linalg::LinearResult<Eigen::Dynamic> RuntimeLinearStep::solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& rhs) {
  switch (method_) {
    case LinearMethod::gepp: return gepp_.solve(J, rhs);
    case LinearMethod::gauss_seidel: return gauss_seidel_.solve(J, rhs);
    case LinearMethod::gsl_lu: return gsl_lu_.solve(J, rhs);
    case LinearMethod::eigen_lu: return eigen_lu_.solve(J, rhs);
    case LinearMethod::inverse2x2: break;
  }
  // inverse2x2: the closed form on the 2x2 system.
  const linalg::LinearResult<2> fixed = linalg::solve2x2(J, rhs);
  linalg::LinearResult<Eigen::Dynamic> result;
  result.x = fixed.x;
  result.status = fixed.status;
  result.iterations = fixed.iterations;
  result.residual_norm = fixed.residual_norm;
  return result;
}

linalg::LinearResult<Eigen::Dynamic> RuntimeLinearStep::solve_with_factors(const Eigen::VectorXd& rhs) const {
  if (!keeps_factors()) throw std::logic_error("only gepp keeps its factors for another right-hand side");
  return gepp_.solve_with_factors(rhs);
}

}  // namespace numlab::nonlinear
