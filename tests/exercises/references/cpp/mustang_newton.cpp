// Reference solution of `numlab exercise mustang-newton` in C++: full Newton on seed 003's Mustang
// loop-closure equations, written from the task's equations.
#include <cmath>
#include <numlab/exercise_protocol.hpp>

#include "newton_loop.hpp"

namespace mustang_newton_reference {

using Vector8 = Eigen::Matrix<double, 8, 1>;
using Matrix8 = Eigen::Matrix<double, 8, 8>;

inline void closure(double theta, const Vector8& v, Vector8& f, Matrix8& J) {
  const double pi = 3.14159265358979323846, bend = pi / 9.0, r = std::sqrt(0.5), third = 4.0 / 3.0;
  const double chord = 2.0 * 2.5 * std::cos(bend);
  const double A = v[0], B = v[1], C = v[2], D = v[3], E = v[4], F = v[5], G = v[6], H = v[7];
  f << -2.5 * std::cos(theta) + 2 * std::cos(A) + 2 * std::cos(B),
      -1 - 2.5 * std::sin(theta) + 2 * std::sin(A) + 2 * std::sin(B),
      -r + chord * std::cos(theta + bend) + third * std::cos(C) - 5 * std::cos(D),
      1 + r + chord * std::sin(theta + bend) - third * std::sin(C) - 5 * std::sin(D),
      third * std::cos(theta + bend) + 4 * std::cos(C - bend) - 4.5 * std::cos(E) - third * std::cos(F),
      third * std::sin(theta + bend) - 4 * std::sin(C - bend) + 4.5 * std::sin(E) - third * std::sin(F),
      std::cos(C + bend) + third * std::cos(F) - third * std::cos(G) + std::cos(H),
      -std::sin(C + bend) + third * std::sin(F) + third * std::sin(G) - std::sin(H);
  J.setZero();
  J(0, 0) = -2 * std::sin(A);  J(0, 1) = -2 * std::sin(B);
  J(1, 0) = 2 * std::cos(A);   J(1, 1) = 2 * std::cos(B);
  J(2, 2) = -third * std::sin(C); J(2, 3) = 5 * std::sin(D);
  J(3, 2) = -third * std::cos(C); J(3, 3) = -5 * std::cos(D);
  J(4, 2) = -4 * std::sin(C - bend); J(4, 4) = 4.5 * std::sin(E); J(4, 5) = third * std::sin(F);
  J(5, 2) = -4 * std::cos(C - bend); J(5, 4) = 4.5 * std::cos(E); J(5, 5) = -third * std::cos(F);
  J(6, 2) = -std::sin(C + bend); J(6, 5) = -third * std::sin(F); J(6, 6) = third * std::sin(G); J(6, 7) = -std::sin(H);
  J(7, 2) = -std::cos(C + bend); J(7, 5) = third * std::cos(F);  J(7, 6) = third * std::cos(G); J(7, 7) = -std::cos(H);
}

inline nlohmann::json solve(const nlohmann::json& request) {
  const double theta = request["crank_angle"].get<double>();
  const auto guess = numlab::exercise::vector(request["guess"]);
  auto evaluate = [theta](const Vector8& x, Vector8& f, Matrix8& J) { closure(theta, x, f, J); };
  return newton_reference::newton<8>(evaluate, Vector8(guess.data()), request["tolerance"].get<double>(),
                                     request["max_iterations"].get<int>(), "angles");
}

}  // namespace mustang_newton_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(mustang_newton_reference::solve); }
#endif
