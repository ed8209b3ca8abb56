#include "methods/seed001_system.hpp"

#include <cmath>

namespace numlab::cli {

void Seed001Closure::jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const {
  // d(L cos t)/dt = -L sin t and d(L sin t)/dt = L cos t, for each term L cos/sin(x_j) above.
  struct Term {
    int row;  // the cosine row; the sine row is row + 1
    int column;
    double length;
  };
  const double r12 = slip_ ? 67.5 : 65.7;  // the seed's slip, on request
  const Term terms[] = {{0, 0, 50.0},   {0, 1, 41.5},  {2, 1, -41.5}, {2, 2, 55.8}, {2, 3, 40.1},
                        {4, 3, 40.1},   {4, 4, -39.4}, {4, 5, 39.3},  {4, 6, -36.7}, {6, 5, -39.3},
                        {6, 7, -61.9},  {8, 6, 36.7},  {8, 8, 49.0},  {8, 9, r12}};
  J.setZero(10, 10);
  for (const Term& term : terms) {
    J(term.row, term.column) = -term.length * std::sin(x(term.column));
    J(term.row + 1, term.column) = term.length * std::cos(x(term.column));
  }
}

Eigen::VectorXd Seed001Closure::seed_estimates() {
  Eigen::VectorXd x(10);
  x << 2.618, -1.745, -2.548, -0.244, -1.030, -1.134, -0.332, 0.977, -1.745, 1.99;
  return x;
}

}  // namespace numlab::cli
