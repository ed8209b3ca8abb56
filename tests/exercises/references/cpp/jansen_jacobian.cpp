// Reference solution of `numlab exercise jansen-jacobian` in C++: seed 000's closure and its
// Jacobian, written from the task's equations.
#include <Eigen/Dense>
#include <cmath>
#include <numlab/exercise_protocol.hpp>

#include "jansen_equations.hpp"

namespace jansen_jacobian_reference {

using jansen_reference::Matrix8;
using jansen_reference::Vector8;
using jansen_reference::closure;

inline nlohmann::json solve(const nlohmann::json& request) {
  const auto theta = numlab::exercise::vector(request["theta"]);
  Vector8 f;
  Matrix8 J;
  closure(request["crank_angle"].get<double>(), Vector8(theta.data()), f, J, jansen_reference::lengths_of(request));
  numlab::exercise::Matrix rows(8, numlab::exercise::Vector(8));
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 8; ++k) rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = J(i, k);
  return {{"f", std::vector<double>(f.data(), f.data() + 8)}, {"J", rows}};
}

}  // namespace jansen_jacobian_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(jansen_jacobian_reference::solve); }
#endif
