// Uses the installed numlab::linalg and numlab::nonlinear, and checks them against GSL (also
// installed with them); exits non-zero if anything disagrees.
#include <cmath>
#include <cstdio>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"

namespace {
// x^2 + y^2 = 4, x = y: root (sqrt 2, sqrt 2).
struct Circle {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Eigen::Vector2d& x, Eigen::Vector2d& f) const { f << x.squaredNorm() - 4.0, x(0) - x(1); }
  void jacobian(const Eigen::Vector2d& x, Eigen::Matrix2d& J) const { J << 2 * x(0), 2 * x(1), 1.0, -1.0; }
};
}  // namespace

int main() {
  Eigen::Matrix3d A;
  A << 2, 1, -1, -3, -1, 2, -2, 1, 2;
  const Eigen::Vector3d b(8, -11, -3);
  const auto gepp = numlab::linalg::gauss_elimination<3>(A, b);
  const auto gsl = numlab::linalg::gsl_lu_solve(A, b);
  const double linear_difference = (gepp.x - gsl.x).lpNorm<Eigen::Infinity>();
  std::printf("numlab consumer: GEPP x = (%g, %g, %g), status %s, |x - x_gsl| = %.2g\n", gepp.x(0), gepp.x(1),
              gepp.x(2), numlab::to_string(gepp.status).data(), linear_difference);

  numlab::nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-14;  // |x - x*| <~ ||J^-1|| ||f||, and ||J^-1|| < 1 near the root
  const auto newton = numlab::nonlinear::newton_solve(Circle{}, Eigen::Vector2d(1.0, 2.0), options);
  const auto rosenbrock = numlab::nonlinear::make_test_problem("rosenbrock");
  const auto hybrid =
      numlab::nonlinear::gsl_multiroot_solve(*rosenbrock.system, rosenbrock.standard_start, "hybridsj");
  const double root_error = (newton.x - Eigen::Vector2d::Constant(std::sqrt(2.0))).lpNorm<Eigen::Infinity>();
  std::printf("numlab consumer: Newton %s in %d iterations, error %.2g; GSL hybridsj on Rosenbrock %s\n",
              numlab::to_string(newton.status).data(), newton.iterations, root_error,
              numlab::to_string(hybrid.status).data());

  const bool ok = gepp.status == numlab::Status::converged && linear_difference < 1e-14 &&
                  newton.status == numlab::Status::converged && root_error < 1e-13 &&
                  hybrid.status == numlab::Status::converged;
  return ok ? 0 : 1;
}
