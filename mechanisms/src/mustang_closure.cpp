#include "numlab/mechanisms/mustang_closure.hpp"

#include <cmath>

namespace numlab::mechanisms {

namespace {
// The fixed points' offsets used by loops 1 and 2 (docs/mechanisms.md).
const Eigen::Vector2d P0(std::sqrt(0.5), 0.0), P1(0.0, std::sqrt(0.5)), P2(0.0, 1.0 + std::sqrt(0.5));
}  // namespace

void MustangClosure::set_crank_angle(double theta) {
  theta_ = theta;
  input_ = Eigen::Vector2d(std::cos(theta), std::sin(theta));
  bent_ = Eigen::Vector2d(std::cos(theta + lengths_.bend), std::sin(theta + lengths_.bend));
}

LoopTerms MustangClosure::loop(int k, const Vector& x) const {
  const MustangLengths& L = lengths_;
  const double C = x(2), F = x(5);
  switch (k) {
    case 0:  // P1 + l1_3 u(A) + l3_4 u(B) = P4 = P2 + l2_4 u(theta)
      return {P1 - P2 - L.l2_4 * input_, {L.l1_3, L.l1_3}, {L.l3_4, L.l3_4}};
    case 1:  // P6 = P2 + |2 6| u(theta + 20) = P0 + l0_5 u(D) + l5_6 u(pi - C)
      return {P2 - P0 + L.chord2_6() * bent_, {L.l5_6, -L.l5_6}, {-L.l0_5, -L.l0_5}};
    case 2:  // P10 = P6 + l6_7 u(theta + 20) + l7_10 u(pi - E) = P6 + l6_8 u(pi - C + 20) + l10_8 u(F)
      return {L.l6_7 * bent_ + L.l6_8 * Eigen::Vector2d(std::cos(C - L.bend), -std::sin(C - L.bend)),
              {-L.l7_10, L.l7_10},
              {-L.l10_8, -L.l10_8}};
    default:  // P11 = P8 + l10_8 u(F) + l10_11 u(pi - G) = P8 + l8_9 u(pi - C - 20) + l9_11 u(pi - H)
      return {L.l8_9 * Eigen::Vector2d(std::cos(C + L.bend), -std::sin(C + L.bend)) +
                  L.l10_8 * Eigen::Vector2d(std::cos(F), std::sin(F)),
              {-L.l10_11, L.l10_11},
              {L.l9_11, -L.l9_11}};
  }
}

void MustangClosure::residual_and_jacobian(const Vector& x, Vector& f, Matrix& J) const {
  const MustangLengths& L = lengths_;
  J.setZero();
  for (int k = 0; k < loops; ++k) {
    // f_k = known + (a_x cos alpha, a_y sin alpha) + (b_x cos beta, b_y sin beta)
    const LoopTerms t = loop(k, x);
    const double ca = std::cos(x(2 * k)), sa = std::sin(x(2 * k));
    const double cb = std::cos(x(2 * k + 1)), sb = std::sin(x(2 * k + 1));
    f(2 * k) = t.known.x() + t.a.x() * ca + t.b.x() * cb;
    f(2 * k + 1) = t.known.y() + t.a.y() * sa + t.b.y() * sb;
    // Its diagonal block: d/d alpha and d/d beta.
    J(2 * k, 2 * k) = -t.a.x() * sa;
    J(2 * k, 2 * k + 1) = -t.b.x() * sb;
    J(2 * k + 1, 2 * k) = t.a.y() * ca;
    J(2 * k + 1, 2 * k + 1) = t.b.y() * cb;
  }
  // Below the diagonal: loop 3's known part depends on C, loop 4's on C and F.
  const double C = x(2), F = x(5);
  J(4, 2) = -L.l6_8 * std::sin(C - L.bend);
  J(5, 2) = -L.l6_8 * std::cos(C - L.bend);
  J(6, 2) = -L.l8_9 * std::sin(C + L.bend);
  J(7, 2) = -L.l8_9 * std::cos(C + L.bend);
  J(6, 5) = -L.l10_8 * std::sin(F);
  J(7, 5) = L.l10_8 * std::cos(F);
}

MustangClosure::Vector MustangClosure::seed_guess() {
  constexpr double first = std::numbers::pi / 18.0, second = std::numbers::pi / 2.0;
  Vector x;
  x << first, second, first, second, first, second, first, second;
  return x;
}

}  // namespace numlab::mechanisms
