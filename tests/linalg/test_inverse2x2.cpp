#include <Eigen/LU>
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

// A subnormal matrix such as 1e-320 I must not give non_finite: a scaling by 2^1063 would go beyond
// the doubles. Every scale below is a power of two times small integers, so A and b are exact, and
// x = [2 1; 1 3]^-1 (1, 2) = (0.2, 0.6) at every scale; Eigen's LU is the second reference where
// its own elimination keeps its digits (among subnormals its multipliers and updates lose bits:
// at 2^-1070 it is 1e-2 off, while the closed form, scaled first, is not).
TEST_CASE("The 2x2 closed form solves at every scale: subnormal, huge and mixed", "[inverse2x2][scale][honesty]") {
  Eigen::Matrix2d shape;
  shape << 2, 1, 1, 3;
  const Eigen::Vector2d expected(0.2, 0.6);
  for (const int power : {-1070, -1062, -1030, -1000, -400, 0, 400, 1000, 1020}) {
    const double scale = std::ldexp(1.0, power);
    INFO("scale 2^" << power);
    const Eigen::Matrix2d A = shape * scale;
    const Eigen::Vector2d b = Eigen::Vector2d(1.0, 2.0) * scale;
    const Eigen::Vector2d eigen = A.partialPivLu().solve(b);
    for (const LinearResult<2>& solved : {solve2x2(A, b), ClosedForm2x2().solve_prechecked(A, b)}) {
      REQUIRE(solved.status == Status::converged);
      // kappa([2 1; 1 3]) = 2.6: a few eps.
      CHECK((solved.x - expected).lpNorm<Eigen::Infinity>() <= 8 * eps);
      if (power >= -1000) CHECK((solved.x - eigen).lpNorm<Eigen::Infinity>() <= 8 * eps);
    }
    const Inverse2x2 inverse = inverse2x2(A);
    // A^-1 = shape^-1 / scale is a double only for scale >= 2^-1022 or so; beyond, non_finite (no
    // false converged), while the solve above still gives x.
    const bool representable = power > -1020;
    CHECK(inverse.status == (representable ? Status::converged : Status::non_finite));
    CHECK(inverse.condition_number == Approx(svd_condition(shape)).epsilon(1e-14));
    if (representable) CHECK(((inverse.inverse * scale) - shape.inverse()).cwiseAbs().maxCoeff() <= 8 * eps);
  }
  // The case: 1e-320 I, b = 1e-320 (1, 1).
  const double tiny = 1e-320;
  const LinearResult<2> identity = solve2x2(tiny * Eigen::Matrix2d::Identity(), Eigen::Vector2d(tiny, tiny));
  REQUIRE(identity.status == Status::converged);
  CHECK(identity.x == Eigen::Vector2d(1.0, 1.0));
  const LinearResult<2> huge = solve2x2(1e300 * Eigen::Matrix2d::Identity(), Eigen::Vector2d(1e300, -1e300));
  REQUIRE(huge.status == Status::converged);
  CHECK(huge.x == Eigen::Vector2d(1.0, -1.0));
  // Mixed scales, far apart but well conditioned by columns: diag(1e150, 1e140) and a triangle of tiny entries.
  Eigen::Matrix2d mixed;
  mixed << 1e150, 0, 0, 1e140;
  Eigen::Matrix2d small;
  small << 1e-310, 1e-315, 0, 1e-312;
  for (const Eigen::Matrix2d& A : {mixed, small}) {
    const Eigen::Vector2d b = A * Eigen::Vector2d(1.0, -3.0);
    const Eigen::Vector2d eigen = A.partialPivLu().solve(b);
    const LinearResult<2> solved = solve2x2(A, b);
    INFO("A = " << A);
    REQUIRE(solved.status == Status::converged);
    // kappa up to 1e10 for diag(1e150, 1e140): relative error within kappa eps of Eigen's.
    CHECK((solved.x - eigen).lpNorm<Eigen::Infinity>() <= 1e-4 * 3.0);
    CHECK((solved.x - Eigen::Vector2d(1.0, -3.0)).lpNorm<Eigen::Infinity>() <= 1e-4 * 3.0);
  }
  // Still singular to working precision when it is: diag(1, 1e-320), kappa = 1e320.
  Eigen::Matrix2d lopsided;
  lopsided << 1, 0, 0, 1e-320;
  CHECK(solve2x2(lopsided, Eigen::Vector2d(1, 1)).status == Status::singular);
}
