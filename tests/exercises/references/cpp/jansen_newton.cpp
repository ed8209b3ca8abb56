// Reference solution of `numlab exercise jansen-newton` in C++: full Newton on seed 000's closure.
#include <numlab/exercise_protocol.hpp>

#include "jansen_equations.hpp"
#include "newton_loop.hpp"

namespace jansen_newton_reference {

inline nlohmann::json solve(const nlohmann::json& request) {
  const double crank = request["crank_angle"].get<double>();
  const auto start = numlab::exercise::vector(request["theta0"]);
  const jansen_reference::Lengths lengths = jansen_reference::lengths_of(request);
  auto closure = [crank, lengths](const jansen_reference::Vector8& x, jansen_reference::Vector8& f,
                                  jansen_reference::Matrix8& J) {
    jansen_reference::closure(crank, x, f, J, lengths);
  };
  return newton_reference::newton<8>(closure, jansen_reference::Vector8(start.data()), request["tolerance"].get<double>(),
                                     request["max_iterations"].get<int>(), "theta");
}

}  // namespace jansen_newton_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(jansen_newton_reference::solve); }
#endif
