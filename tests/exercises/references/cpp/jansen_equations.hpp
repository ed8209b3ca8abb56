#pragma once
// Seed 000's 8-equation Jansen closure and its Jacobian, written from the task's equations (shared
// by the jansen-jacobian and jansen-newton reference solutions).
#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>

namespace jansen_reference {

// Lengths of seed 000: crank li, links l1 ... l8, offsets a (down) and b (left) of P1.
struct Lengths {
  double li = 15, l1 = 50, l2 = 41.5, l3 = 55.8, l4 = 40.1, l5 = 39.4, l6 = 61.9, l7 = 39.3, l8 = 36.7;
  double a = 7.8, b = 38;
};

// The request's "lengths" (a variant's, TASK.md "Your variant") when it has them, else seed 000's.
inline Lengths lengths_of(const nlohmann::json& request) {
  Lengths L;
  if (!request.contains("lengths")) return L;
  const nlohmann::json& given = request["lengths"];
  L = {given["crank"], given["l1"], given["l2"], given["l3"], given["l4"], given["l5"],
       given["l6"],    given["l7"], given["l8"], given["a"],  given["b"]};
  return L;
}

using Vector8 = Eigen::Matrix<double, 8, 1>;
using Matrix8 = Eigen::Matrix<double, 8, 8>;

inline void closure(double crank, const Vector8& t, Vector8& f, Matrix8& J, const Lengths& given = {}) {
  const auto& [li, l1, l2, l3, l4, l5, l6, l7, l8, a, b] = given;
  const double Y = li * std::sin(crank) + a, X = li * std::cos(crank) + b;
  const Vector8 s = t.array().sin(), c = t.array().cos();
  f << Y + l1 * s[0] - l2 * s[1], X + l1 * c[0] - l2 * c[1],
      Y + l1 * s[0] + l3 * s[2] - l4 * s[3], X + l1 * c[0] + l3 * c[2] - l4 * c[3],
      Y + l6 * s[5] - l7 * s[6], X + l6 * c[5] - l7 * c[6],
      Y + l1 * s[0] + l3 * s[2] + l5 * s[4] - l7 * s[6] - l8 * s[7],
      X + l1 * c[0] + l3 * c[2] + l5 * c[4] - l7 * c[6] - l8 * c[7];
  // Row pairs (y, x): each term +-L sin(t_k) / +-L cos(t_k) differentiates to +-L cos / -+L sin.
  const int terms[][3] = {{0, 0, +1}, {0, 1, -1}, {2, 0, +1}, {2, 2, +1}, {2, 3, -1}, {4, 5, +1}, {4, 6, -1},
                          {6, 0, +1}, {6, 2, +1}, {6, 4, +1}, {6, 6, -1}, {6, 7, -1}};
  const double lengths[] = {l1, l2, l3, l4, l5, l6, l7, l8};
  J.setZero();
  for (const auto& term : terms) {
    const int row = term[0], k = term[1];
    const double L = term[2] * lengths[k];
    J(row, k) = L * c[k];
    J(row + 1, k) = -L * s[k];
  }
}

}  // namespace jansen_reference
