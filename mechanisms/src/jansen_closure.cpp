#include "numlab/mechanisms/jansen_closure.hpp"

#include <cmath>

namespace numlab::mechanisms {

template <typename Sines>
void JansenClosureOf<Sines>::set_crank_angle(double crank_angle) {
  double c, s;
  Sines::one(crank_angle, c, s);
  crank_x_ = lengths_.crank * c + lengths_.b;
  crank_y_ = lengths_.crank * s + lengths_.a;
}

template <typename Sines>
void JansenClosureOf<Sines>::residual_and_jacobian(const Vector& theta, Vector& f, Matrix& J) const {
  const JansenLengths& L = lengths_;
  Vector c, s;  // cos theta_k, sin theta_k, once each
  Sines::evaluate(theta, c, s);
  // Sine rows (odd equations) and cosine rows (even equations) of seed 000 eqs (1)-(8).
  f(0) = crank_y_ + L.l1 * s(0) - L.l2 * s(1);
  f(1) = crank_x_ + L.l1 * c(0) - L.l2 * c(1);
  f(2) = crank_y_ + L.l1 * s(0) + L.l3 * s(2) - L.l4 * s(3);
  f(3) = crank_x_ + L.l1 * c(0) + L.l3 * c(2) - L.l4 * c(3);
  f(4) = crank_y_ + L.l6 * s(5) - L.l7 * s(6);
  f(5) = crank_x_ + L.l6 * c(5) - L.l7 * c(6);
  f(6) = crank_y_ + L.l1 * s(0) + L.l3 * s(2) + L.l5 * s(4) - L.l7 * s(6) - L.l8 * s(7);
  f(7) = crank_x_ + L.l1 * c(0) + L.l3 * c(2) + L.l5 * c(4) - L.l7 * c(6) - L.l8 * c(7);

  // d(L sin t)/dt = L cos t, d(L cos t)/dt = -L sin t.
  J.setZero();
  J(0, 0) = L.l1 * c(0);  J(0, 1) = -L.l2 * c(1);
  J(1, 0) = -L.l1 * s(0); J(1, 1) = L.l2 * s(1);
  J(2, 0) = L.l1 * c(0);  J(2, 2) = L.l3 * c(2);  J(2, 3) = -L.l4 * c(3);
  J(3, 0) = -L.l1 * s(0); J(3, 2) = -L.l3 * s(2); J(3, 3) = L.l4 * s(3);
  J(4, 5) = L.l6 * c(5);  J(4, 6) = -L.l7 * c(6);
  J(5, 5) = -L.l6 * s(5); J(5, 6) = L.l7 * s(6);
  J(6, 0) = L.l1 * c(0);  J(6, 2) = L.l3 * c(2);  J(6, 4) = L.l5 * c(4);  J(6, 6) = -L.l7 * c(6); J(6, 7) = -L.l8 * c(7);
  J(7, 0) = -L.l1 * s(0); J(7, 2) = -L.l3 * s(2); J(7, 4) = -L.l5 * s(4); J(7, 6) = L.l7 * s(6);  J(7, 7) = L.l8 * s(7);
}

template <typename Sines>
typename JansenClosureOf<Sines>::Vector JansenClosureOf<Sines>::seed_estimates() {
  Vector theta;
  theta << 2.62, 1.40, 3.73, 2.90, 5.26, 4.12, 5.14, 2.81;
  return theta;
}

template class JansenClosureOf<LibrarySines>;
template class JansenClosureOf<TableSines>;

}  // namespace numlab::mechanisms
