#include "numlab/mechanisms/jansen10_closure.hpp"

#include <cmath>

namespace numlab::mechanisms {

template <typename Sines>
Jansen10ClosureOf<Sines>::Jansen10ClosureOf(double crank_angle, JansenLengths lengths, JansenFootLengths foot)
    : lengths_(lengths),
      terms_{{{0, 0, lengths.l1},  {0, 1, lengths.l2},   {2, 1, -lengths.l2}, {2, 2, lengths.l3},  {2, 3, lengths.l4},
              {4, 3, lengths.l4},  {4, 4, -lengths.l5},  {4, 5, lengths.l7},  {4, 6, -lengths.l8}, {6, 5, -lengths.l7},
              {6, 7, -lengths.l6}, {8, 6, lengths.l8},   {8, 8, foot.l9},     {8, 9, foot.l10}}} {
  set_crank_angle(crank_angle);
}

template <typename Sines>
void Jansen10ClosureOf<Sines>::set_crank_angle(double crank_angle) {
  double c, s;
  Sines::one(crank_angle, c, s);
  crank_x_ = lengths_.b + lengths_.crank * c;
  crank_y_ = lengths_.a + lengths_.crank * s;
}

template <typename Sines>
void Jansen10ClosureOf<Sines>::residual_and_jacobian(const Vector& theta, Vector& f, Matrix& J) const {
  Vector c, s;  // each sine and cosine once, for f and J
  Sines::evaluate(theta, c, s);
  f.setZero();
  f(0) = f(6) = crank_x_;
  f(1) = f(7) = crank_y_;
  J.setZero();
  for (const Term& term : terms_) {
    f(term.row) += term.length * c(term.column);
    f(term.row + 1) += term.length * s(term.column);
    J(term.row, term.column) = -term.length * s(term.column);  // d(L cos t)/dt
    J(term.row + 1, term.column) = term.length * c(term.column);  // d(L sin t)/dt
  }
}

template class Jansen10ClosureOf<LibrarySines>;
template class Jansen10ClosureOf<TableSines>;

}  // namespace numlab::mechanisms
