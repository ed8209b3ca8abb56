// Reference solution of `numlab exercise polyfit` in C++: least squares by column-pivoted
// Householder QR of the Vandermonde matrix with unit-length columns.
#include <Eigen/Dense>
#include <numlab/exercise_protocol.hpp>
#include <set>

namespace polyfit_reference {

inline nlohmann::json solve(const nlohmann::json& request) {
  const auto xs = numlab::exercise::vector(request["x"]);
  const auto ys = numlab::exercise::vector(request["y"]);
  const int degree = request["degree"].get<int>();
  if (std::set<double>(xs.begin(), xs.end()).size() < static_cast<std::size_t>(degree + 1)) {
    return {{"status", "singular"}};
  }
  const Eigen::Index m = static_cast<Eigen::Index>(xs.size());
  Eigen::MatrixXd V(m, degree + 1);
  for (Eigen::Index i = 0; i < m; ++i) {
    double power = 1.0;
    for (int k = 0; k <= degree; ++k, power *= xs[static_cast<std::size_t>(i)]) V(i, k) = power;
  }
  const Eigen::VectorXd scale = V.colwise().norm().transpose();
  const Eigen::MatrixXd unit = V * scale.cwiseInverse().asDiagonal();
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(ys.data(), m);
  const Eigen::VectorXd b = unit.colPivHouseholderQr().solve(y).cwiseQuotient(scale);
  return {{"coefficients", std::vector<double>(b.data(), b.data() + b.size())}};
}

}  // namespace polyfit_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(polyfit_reference::solve); }
#endif
