// Solves one system with the installed numlab::linalg and checks it against GSL LU (also installed);
// exits non-zero if anything disagrees.
#include <cstdio>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gsl_reference.hpp"

int main() {
  Eigen::Matrix3d A;
  A << 2, 1, -1, -3, -1, 2, -2, 1, 2;
  const Eigen::Vector3d b(8, -11, -3);
  const auto gepp = numlab::linalg::gauss_elimination<3>(A, b);
  const auto gsl = numlab::linalg::gsl_lu_solve(A, b);
  const double difference = (gepp.x - gsl.x).lpNorm<Eigen::Infinity>();
  std::printf("numlab consumer: x = (%g, %g, %g), status %s, |x - x_gsl| = %.2g\n", gepp.x(0), gepp.x(1), gepp.x(2),
              numlab::to_string(gepp.status).data(), difference);
  return gepp.status == numlab::Status::converged && difference < 1e-14 ? 0 : 1;
}
