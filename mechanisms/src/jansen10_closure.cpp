#include "numlab/mechanisms/jansen10_closure.hpp"

#include <cmath>

namespace numlab::mechanisms {

namespace {
// Each closure term is L cos(x_j) in a cosine row and L sin(x_j) in the sine row below it.
struct Term {
  int row;  // the cosine row
  int column;
  double length;
};
constexpr Term terms[] = {{0, 0, 50.0},  {0, 1, 41.5},  {2, 1, -41.5}, {2, 2, 55.8},  {2, 3, 40.1},
                          {4, 3, 40.1},  {4, 4, -39.4}, {4, 5, 39.3},  {4, 6, -36.7}, {6, 5, -39.3},
                          {6, 7, -61.9}, {8, 6, 36.7},  {8, 8, 49.0},  {8, 9, 65.7}};
}  // namespace

template <typename Sines>
void Jansen10ClosureOf<Sines>::set_crank_angle(double crank_angle) {
  const JansenLengths lengths;
  double c, s;
  Sines::one(crank_angle, c, s);
  crank_x_ = lengths.b + lengths.crank * c;
  crank_y_ = lengths.a + lengths.crank * s;
}

template <typename Sines>
void Jansen10ClosureOf<Sines>::residual_and_jacobian(const Vector& theta, Vector& f, Matrix& J) const {
  Vector c, s;  // each sine and cosine once, for f and J
  Sines::evaluate(theta, c, s);
  f.setZero();
  f(0) = f(6) = crank_x_;
  f(1) = f(7) = crank_y_;
  J.setZero();
  for (const Term& term : terms) {
    f(term.row) += term.length * c(term.column);
    f(term.row + 1) += term.length * s(term.column);
    J(term.row, term.column) = -term.length * s(term.column);  // d(L cos t)/dt
    J(term.row + 1, term.column) = term.length * c(term.column);  // d(L sin t)/dt
  }
}

template class Jansen10ClosureOf<LibrarySines>;
template class Jansen10ClosureOf<TableSines>;

}  // namespace numlab::mechanisms
