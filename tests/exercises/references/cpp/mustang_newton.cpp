// Reference solution of `numlab exercise mustang-newton` in C++: full Newton on seed 003's Mustang
// loop-closure equations, written from the task's equations.
#include <cmath>
#include <utility>
#include <numlab/exercise_protocol.hpp>

#include "newton_loop.hpp"

namespace mustang_newton_reference {

using Vector8 = Eigen::Matrix<double, 8, 1>;
using Matrix8 = Eigen::Matrix<double, 8, 8>;

// Seed 003's lengths |a b| as l_a_b; a request with a variant carries its own as "lengths".
struct Lengths {
  double l1_3 = 2, l3_4 = 2, l2_4 = 2.5, l0_5 = 5, l5_6 = 4.0 / 3.0, l6_7 = 4.0 / 3.0, l6_8 = 4, l8_9 = 1, l7_10 = 4.5;
  double l10_8 = 4.0 / 3.0, l10_11 = 4.0 / 3.0, l9_11 = 1;
};

inline Lengths lengths_of(const nlohmann::json& request) {
  Lengths L;
  if (!request.contains("lengths")) return L;
  const nlohmann::json& given = request["lengths"];
  for (auto [name, field] : {std::pair{"l1_3", &L.l1_3}, {"l3_4", &L.l3_4}, {"l2_4", &L.l2_4}, {"l0_5", &L.l0_5},
                             {"l5_6", &L.l5_6}, {"l6_7", &L.l6_7}, {"l6_8", &L.l6_8}, {"l8_9", &L.l8_9},
                             {"l7_10", &L.l7_10}, {"l10_8", &L.l10_8}, {"l10_11", &L.l10_11}, {"l9_11", &L.l9_11}}) {
    *field = given.at(name).get<double>();
  }
  return L;
}

inline void closure(double theta, const Vector8& v, const Lengths& L, Vector8& f, Matrix8& J) {
  const double pi = 3.14159265358979323846, bend = pi / 9.0, r = std::sqrt(0.5);
  const double chord = 2.0 * L.l2_4 * std::cos(bend);
  const double A = v[0], B = v[1], C = v[2], D = v[3], E = v[4], F = v[5], G = v[6], H = v[7];
  f << -L.l2_4 * std::cos(theta) + L.l1_3 * std::cos(A) + L.l3_4 * std::cos(B),
      -1 - L.l2_4 * std::sin(theta) + L.l1_3 * std::sin(A) + L.l3_4 * std::sin(B),
      -r + chord * std::cos(theta + bend) + L.l5_6 * std::cos(C) - L.l0_5 * std::cos(D),
      1 + r + chord * std::sin(theta + bend) - L.l5_6 * std::sin(C) - L.l0_5 * std::sin(D),
      L.l6_7 * std::cos(theta + bend) + L.l6_8 * std::cos(C - bend) - L.l7_10 * std::cos(E) - L.l10_8 * std::cos(F),
      L.l6_7 * std::sin(theta + bend) - L.l6_8 * std::sin(C - bend) + L.l7_10 * std::sin(E) - L.l10_8 * std::sin(F),
      L.l8_9 * std::cos(C + bend) + L.l10_8 * std::cos(F) - L.l10_11 * std::cos(G) + L.l9_11 * std::cos(H),
      -L.l8_9 * std::sin(C + bend) + L.l10_8 * std::sin(F) + L.l10_11 * std::sin(G) - L.l9_11 * std::sin(H);
  J.setZero();
  J(0, 0) = -L.l1_3 * std::sin(A);  J(0, 1) = -L.l3_4 * std::sin(B);
  J(1, 0) = L.l1_3 * std::cos(A);   J(1, 1) = L.l3_4 * std::cos(B);
  J(2, 2) = -L.l5_6 * std::sin(C); J(2, 3) = L.l0_5 * std::sin(D);
  J(3, 2) = -L.l5_6 * std::cos(C); J(3, 3) = -L.l0_5 * std::cos(D);
  J(4, 2) = -L.l6_8 * std::sin(C - bend); J(4, 4) = L.l7_10 * std::sin(E); J(4, 5) = L.l10_8 * std::sin(F);
  J(5, 2) = -L.l6_8 * std::cos(C - bend); J(5, 4) = L.l7_10 * std::cos(E); J(5, 5) = -L.l10_8 * std::cos(F);
  J(6, 2) = -L.l8_9 * std::sin(C + bend); J(6, 5) = -L.l10_8 * std::sin(F); J(6, 6) = L.l10_11 * std::sin(G);
  J(6, 7) = -L.l9_11 * std::sin(H);
  J(7, 2) = -L.l8_9 * std::cos(C + bend); J(7, 5) = L.l10_8 * std::cos(F);  J(7, 6) = L.l10_11 * std::cos(G);
  J(7, 7) = -L.l9_11 * std::cos(H);
}

inline nlohmann::json solve(const nlohmann::json& request) {
  const double theta = request["crank_angle"].get<double>();
  const auto guess = numlab::exercise::vector(request["guess"]);
  const Lengths lengths = lengths_of(request);
  auto evaluate = [theta, lengths](const Vector8& x, Vector8& f, Matrix8& J) { closure(theta, x, lengths, f, J); };
  return newton_reference::newton<8>(evaluate, Vector8(guess.data()), request["tolerance"].get<double>(),
                                     request["max_iterations"].get<int>(), "angles");
}

}  // namespace mustang_newton_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(mustang_newton_reference::solve); }
#endif
