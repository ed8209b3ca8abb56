#include <Eigen/SVD>
#include <catch2/catch.hpp>
#include <cmath>

#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "reference_tolerance.hpp"

using namespace numlab;
using namespace numlab::linalg;
using numlab::test::eps;
using numlab::test::relative_difference;

namespace {
double svd_condition(const Eigen::Matrix2d& A) {
  const Eigen::Vector2d sigma = Eigen::JacobiSVD<Eigen::Matrix2d>(A).singularValues();
  return sigma(0) / sigma(1);
}
}  // namespace

TEST_CASE("The 2x2 closed form agrees with GSL LU, and its kappa with the SVD", "[inverse2x2][reference]") {
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Eigen::Matrix2d A = random_matrix(2, seed);
    const Eigen::Vector2d b = A * Eigen::Vector2d::Ones();
    const Inverse2x2 inverse = inverse2x2(A);
    const double kappa = svd_condition(A);
    INFO("seed " << seed << ", kappa " << kappa);
    REQUIRE(inverse.status == Status::converged);
    CHECK(inverse.condition_number == Approx(kappa).epsilon(1e-6 + 10 * kappa * eps));
    CHECK((A * inverse.inverse - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() <= 10 * kappa * eps);
    const LinearResult<2> closed = solve2x2(A, b);
    const auto gsl = gsl_lu_solve(A, b);
    CHECK(relative_difference(closed.x, gsl.x) <= 20 * kappa * eps);
  }
}

TEST_CASE("The 2x2 singularity test is relative to scale", "[inverse2x2][scale]") {
  Eigen::Matrix2d A;
  A << 4, 3, 6, 3;
  const Inverse2x2 reference = inverse2x2(A);
  for (double scale : {1e-300, 1e-200, 1e-7, 1e7, 1e200, 1e300}) {
    const Inverse2x2 scaled = inverse2x2(scale * A);
    INFO("scale " << scale);
    REQUIRE(scaled.status == Status::converged);
    CHECK(scaled.condition_number == Approx(reference.condition_number).epsilon(1e-14));
    CHECK((scaled.inverse * scale - reference.inverse).cwiseAbs().maxCoeff() <= 1e-14);
  }
  // A perfectly conditioned matrix with a tiny determinant is not singular.
  CHECK(inverse2x2(1e-7 * Eigen::Matrix2d::Identity()).status == Status::converged);
}

TEST_CASE("Nearly singular and singular 2x2 matrices", "[inverse2x2][failure]") {
  for (double d : {1e-2, 1e-6, 1e-10, 1e-14}) {
    Eigen::Matrix2d A;
    A << 1, 1, 1, 1 + d;
    const Inverse2x2 inverse = inverse2x2(A);
    INFO("d = " << d);
    CHECK(inverse.status == Status::converged);
    // A is symmetric with eigenvalues 1 + d/2 +- sqrt(1 + d^2/4): kappa = 4/d + 1 + O(d). The
    // perturbation is rounded when 1 + d is stored, so use the stored one. (An SVD cannot serve as the
    // reference here: it finds sigma_min ~ d/2 only to an absolute error of about eps.)
    const double stored = A(1, 1) - 1.0;
    CHECK(inverse.condition_number == Approx(4.0 / stored + 1.0).epsilon(d));
  }
  Eigen::Matrix2d rounded_away;
  rounded_away << 1, 1, 1, 1 + 1e-16;  // 1 + 1e-16 == 1
  CHECK(inverse2x2(rounded_away).status == Status::singular);
  Eigen::Matrix2d parallel;
  parallel << 1, 2, 2, 4;
  const Inverse2x2 singular = inverse2x2(parallel);
  CHECK(singular.status == Status::singular);
  CHECK(singular.determinant == 0.0);
  CHECK(std::isinf(singular.condition_number));
  CHECK(singular.inverse.array().isNaN().all());
  const LinearResult<2> solved = solve2x2(parallel, Eigen::Vector2d(1, 2));
  CHECK(solved.status == Status::singular);
  CHECK(solved.x.array().isNaN().all());
  CHECK(inverse2x2(Eigen::Matrix2d::Zero()).status == Status::singular);
}

TEST_CASE("The 2x2 closed form rejects non-finite input", "[inverse2x2][bad-input]") {
  Eigen::Matrix2d A = Eigen::Matrix2d::Identity();
  A(0, 1) = INFINITY;
  CHECK_THROWS_WITH(inverse2x2(A), Catch::Matchers::Contains("non-finite"));
  CHECK_THROWS_AS(solve2x2(Eigen::Matrix2d::Identity(), Eigen::Vector2d(NAN, 1)), std::invalid_argument);
}

TEST_CASE("Newton's 2x2 path (solve_prechecked) agrees with solve2x2, scaled or not", "[inverse2x2][prechecked]") {
  const ClosedForm2x2 closed_form;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Eigen::Matrix2d A = random_matrix(2, seed);
    const Eigen::Vector2d b = A * Eigen::Vector2d(1.0, -2.0);
    const double kappa = svd_condition(A);
    INFO("seed " << seed << ", kappa " << kappa);
    const LinearResult<2> fast = closed_form.solve_prechecked(A, b);
    REQUIRE(fast.status == Status::converged);
    CHECK(relative_difference(fast.x, solve2x2(A, b).x) <= 10 * kappa * eps);
    CHECK(std::isnan(fast.residual_norm));  // not computed on this path
  }
  // Outside 2^-200 ... 2^200 the matrix is scaled first, exactly as inverse2x2 does.
  Eigen::Matrix2d A;
  A << 4, 3, 6, 3;
  const Eigen::Vector2d reference = closed_form.solve_prechecked(A, Eigen::Vector2d(1, 1)).x;
  for (double scale : {1e-300, 1e-100, 1e100, 1e300}) {
    INFO("scale " << scale);
    const LinearResult<2> scaled = closed_form.solve_prechecked(scale * A, Eigen::Vector2d(1, 1));
    REQUIRE(scaled.status == Status::converged);
    CHECK((scaled.x * scale - reference).cwiseAbs().maxCoeff() <= 1e-14);
  }
  Eigen::Matrix2d parallel;
  parallel << 1, 2, 2, 4;
  CHECK(closed_form.solve_prechecked(parallel, Eigen::Vector2d(1, 2)).status == Status::singular);
  CHECK(closed_form.solve_prechecked(parallel, Eigen::Vector2d(1, 2)).x.array().isNaN().all());
  CHECK(closed_form.solve_prechecked(Eigen::Matrix2d::Zero(), Eigen::Vector2d(1, 2)).status == Status::singular);
  // A well-conditioned but tiny matrix with a huge right-hand side: x overflows, and says so.
  CHECK(closed_form.solve_prechecked(1e-200 * Eigen::Matrix2d::Identity(), Eigen::Vector2d(1e300, 1)).status ==
        Status::non_finite);
}
