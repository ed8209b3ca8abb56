// Reference solution of `numlab exercise jansen10-jacobian` in C++: seed 001's ten closure
// equations and their Jacobian, written from the task's equations.
#include <Eigen/Dense>
#include <cmath>
#include <numlab/exercise_protocol.hpp>

namespace jansen10_jacobian_reference {

// The crank li, the offsets a (down) and b (left) of P1, and |r3| ... |r12|.
struct Lengths {
  double li = 15, a = 7.8, b = 38;
  double r3 = 50, r4 = 41.5, r5 = 55.8, r6 = 40.1, r7 = 39.4, r8 = 39.3, r9 = 36.7, r10 = 61.9, r11 = 49, r12 = 65.7;
};

// The request's "lengths" (a variant's: crank, a, b, l1 ... l10, where |r3| ... |r12| are l1, l2, l3,
// l4, l5, l7, l8, l6, l9, l10) when it has them, else seed 000's.
inline Lengths lengths_of(const nlohmann::json& request) {
  Lengths L;
  if (!request.contains("lengths")) return L;
  const nlohmann::json& g = request["lengths"];
  L = {g["crank"], g["a"], g["b"], g["l1"], g["l2"], g["l3"], g["l4"], g["l5"], g["l7"], g["l8"], g["l6"], g["l9"], g["l10"]};
  return L;
}

using Vector10 = Eigen::Matrix<double, 10, 1>;
using Matrix10 = Eigen::Matrix<double, 10, 10>;

// t(k) is theta_(k+3). Rows 2p and 2p + 1 are loop p's x and y components.
inline void closure(double crank, const Vector10& t, Vector10& f, Matrix10& J, const Lengths& lengths = {}) {
  const auto& [li, a, b, r3, r4, r5, r6, r7, r8, r9, r10, r11, r12] = lengths;
  const double X = b + li * std::cos(crank), Y = a + li * std::sin(crank);
  const Vector10 s = t.array().sin(), c = t.array().cos();
  f << X + r3 * c[0] + r4 * c[1], Y + r3 * s[0] + r4 * s[1],
      -r4 * c[1] + r5 * c[2] + r6 * c[3], -r4 * s[1] + r5 * s[2] + r6 * s[3],
      r6 * c[3] - r7 * c[4] + r8 * c[5] - r9 * c[6], r6 * s[3] - r7 * s[4] + r8 * s[5] - r9 * s[6],
      X - r8 * c[5] - r10 * c[7], Y - r8 * s[5] - r10 * s[7],
      r9 * c[6] + r11 * c[8] + r12 * c[9], r9 * s[6] + r11 * s[8] + r12 * s[9];
  // Each term +-L cos(t_k) in an x row differentiates to -+L sin(t_k); its +-L sin(t_k) in the y row to +-L cos(t_k).
  struct Term {
    int x_row, k;
    double L;
  };
  const Term terms[] = {{0, 0, r3},  {0, 1, r4},  {2, 1, -r4}, {2, 2, r5},   {2, 3, r6},  {4, 3, r6},  {4, 4, -r7},
                        {4, 5, r8},  {4, 6, -r9}, {6, 5, -r8}, {6, 7, -r10}, {8, 6, r9},  {8, 8, r11}, {8, 9, r12}};
  J.setZero();
  for (const Term& term : terms) {
    J(term.x_row, term.k) = -term.L * s[term.k];
    J(term.x_row + 1, term.k) = term.L * c[term.k];
  }
}

inline nlohmann::json solve(const nlohmann::json& request) {
  const auto theta = numlab::exercise::vector(request["theta"]);
  Vector10 f;
  Matrix10 J;
  closure(request["crank_angle"].get<double>(), Vector10(theta.data()), f, J, lengths_of(request));
  numlab::exercise::Matrix rows(10, numlab::exercise::Vector(10));
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < 10; ++k) rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = J(i, k);
  return {{"f", std::vector<double>(f.data(), f.data() + 10)}, {"J", rows}};
}

}  // namespace jansen10_jacobian_reference

#ifndef NUMLAB_EXERCISE_IN_PROCESS
int main() { return numlab::exercise::serve(jansen10_jacobian_reference::solve); }
#endif
