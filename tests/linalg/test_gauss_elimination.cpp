#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "reference_tolerance.hpp"

using namespace numlab;
using namespace numlab::linalg;
using numlab::test::agreement_tolerance;
using numlab::test::eps;
using numlab::test::relative_difference;

TEST_CASE("GEPP agrees with GSL LU and Eigen PartialPivLU on random systems, n = 1 ... 200", "[gepp][reference]") {
  for (int n = 1; n <= 200; ++n) {
    const GeneratedSystem system = generate_system("random", n, static_cast<unsigned>(n));
    const LinearResult<Eigen::Dynamic> gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
    const LinearResult<Eigen::Dynamic> gsl = gsl_lu_solve(system.A, system.b);
    const LinearResult<Eigen::Dynamic> eigen = EigenLu<Eigen::Dynamic>().solve(system.A, system.b);
    INFO("n = " << n);
    REQUIRE(gepp.status == Status::converged);
    REQUIRE(gsl.status == Status::converged);
    const double tolerance = agreement_tolerance(system.A, gepp.growth_factor);
    CHECK(relative_difference(gepp.x, gsl.x) <= tolerance);
    CHECK(relative_difference(gepp.x, eigen.x) <= tolerance);
    CHECK(relative_difference(gepp.x, system.exact_solution) <= tolerance);
    // Backward stability: the relative residual is of order n * growth * eps whatever kappa is.
    CHECK(relative_residual(system.A, system.b, gepp.x) <= 4.0 * n * gepp.growth_factor * eps);
  }
}

TEST_CASE("GEPP on Hilbert matrices, n <= 12: backward stable, forward error bounded by kappa", "[gepp][hilbert]") {
  for (int n = 1; n <= 12; ++n) {
    const GeneratedSystem system = generate_system("hilbert", n);
    const LinearResult<Eigen::Dynamic> gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
    const LinearResult<Eigen::Dynamic> gsl = gsl_lu_solve(system.A, system.b);
    const LinearResult<Eigen::Dynamic> eigen = EigenLu<Eigen::Dynamic>().solve(system.A, system.b);
    INFO("n = " << n << ", condition estimate " << condition_estimate(system.A));
    REQUIRE(gepp.status == Status::converged);
    // The residual does not depend on kappa: this is the check that means something at every n.
    CHECK(relative_residual(system.A, system.b, gepp.x) <= 4.0 * n * gepp.growth_factor * eps);
    CHECK(relative_residual(system.A, system.b, gsl.x) <= 4.0 * n * eps * 10);
    // Forward agreement is only promised while n * kappa * eps < 1 (n <= 10 here); beyond that the
    // bound exceeds 1 and no digit is guaranteed, so there is nothing honest to assert.
    const double tolerance = agreement_tolerance(system.A, gepp.growth_factor);
    if (tolerance < 1.0) {
      CHECK(relative_difference(gepp.x, gsl.x) <= tolerance);
      CHECK(relative_difference(gepp.x, eigen.x) <= tolerance);
      CHECK(relative_difference(gepp.x, system.exact_solution) <= tolerance);
    }
  }
}

TEST_CASE("Hilbert n = 13 is singular to working precision and GEPP says so", "[gepp][hilbert][failure]") {
  const GeneratedSystem system = generate_system("hilbert", 13);
  REQUIRE(condition_estimate(system.A) * eps > 1.0);
  const LinearResult<Eigen::Dynamic> gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
  CHECK(gepp.status == Status::singular);
  CHECK(gepp.x.array().isNaN().all());
}

TEST_CASE("Wilkinson's matrix: the growth factor is exactly 2^(n-1)", "[gepp][wilkinson]") {
  for (int n = 2; n <= 60; ++n) {
    const GeneratedSystem system = generate_system("wilkinson", n);
    const LinearResult<Eigen::Dynamic> gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
    INFO("n = " << n);
    CHECK(gepp.growth_factor == std::ldexp(1.0, n - 1));
  }
}

TEST_CASE("Wilkinson n = 60: GEPP loses every digit and reports the growth, QR does not", "[gepp][wilkinson][failure]") {
  const GeneratedSystem system = generate_system("wilkinson", 60);
  const LinearResult<Eigen::Dynamic> gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
  const LinearResult<Eigen::Dynamic> qr = gsl_qr_solve(system.A, system.b);
  // No pivot is small, so elimination completes...
  CHECK(gepp.status == Status::converged);
  // ...but the growth 2^59 exceeds 1/eps, and the answer has no correct digit.
  CHECK(gepp.growth_factor * eps > 1.0);
  CHECK(forward_error(gepp.x, system.exact_solution) >= 0.5);
  CHECK(relative_residual(system.A, system.b, gepp.x) > 1e-3);
  // The matrix itself is well conditioned (kappa_1 ~ n): QR keeps its digits.
  CHECK(condition_estimate(system.A) < 100.0);
  CHECK(forward_error(qr.x, system.exact_solution) <= agreement_tolerance(system.A));
}

TEST_CASE("A tiny pivot: no pivoting loses digits, partial pivoting does not", "[gepp][pivoting][failure]") {
  Eigen::MatrixXd A(2, 2);
  A << 1e-14, 1, 1, 1;
  const Eigen::VectorXd exact = Eigen::VectorXd::Ones(2);
  const Eigen::VectorXd b = A * exact;
  GaussEliminationOptions no_pivoting;
  no_pivoting.pivoting = Pivoting::none;
  const auto naive = gauss_elimination<Eigen::Dynamic>(A, b, no_pivoting);
  const auto pivoted = gauss_elimination<Eigen::Dynamic>(A, b);
  REQUIRE(naive.status == Status::converged);
  CHECK(naive.growth_factor > 1e13);                  // the multiplier 1/d shows in U
  CHECK(forward_error(naive.x, exact) > 1e-4);        // about 1e-16 / 1e-14 lost
  CHECK(forward_error(pivoted.x, exact) <= 4 * eps);  // kappa ~ 4: full accuracy
  CHECK(pivoted.growth_factor <= 2.0);

  // Below n * eps * max|a_ij| the pivot is negligible: 'singular', never a division by it.
  A(0, 0) = 1e-17;
  CHECK(gauss_elimination<Eigen::Dynamic>(A, b, no_pivoting).status == Status::singular);
  CHECK(gauss_elimination<Eigen::Dynamic>(A, b).status == Status::converged);
}

TEST_CASE("Singular matrices end with status singular, and no solution is passed off", "[gepp][singular]") {
  // The pivot test (|pivot| <= n * eps * max|a_ij|) sees most exactly singular matrices, but rounding
  // in the elimination can leave the last pivot a few times above it. Then the condition estimate
  // exceeds 1/eps, which the CLI turns into a warning: either way nothing passes for a good answer.
  int flagged = 0;
  for (int n = 2; n <= 50; ++n) {
    const GeneratedSystem system = generate_system("singular", n, static_cast<unsigned>(n));
    const auto gepp = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
    INFO("n = " << n);
    if (gepp.status == Status::singular) {
      ++flagged;
      CHECK(gepp.x.array().isNaN().all());
    } else {
      CHECK(gepp.status == Status::converged);
      CHECK(condition_estimate(system.A) * eps >= 1.0);
    }
  }
  CHECK(flagged >= 40);  // of 49
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(4, 4);
  CHECK(gauss_elimination<Eigen::Dynamic>(zero, Eigen::VectorXd::Ones(4)).status == Status::singular);
  Eigen::MatrixXd repeated_row = Eigen::MatrixXd::Identity(3, 3);
  repeated_row.row(2) = repeated_row.row(0);
  CHECK(gauss_elimination<Eigen::Dynamic>(repeated_row, Eigen::VectorXd::Ones(3)).status == Status::singular);
}

TEST_CASE("Overflow during elimination gives non_finite", "[gepp][failure]") {
  Eigen::MatrixXd A(2, 2);
  A << 1e308, 1e308, -1e308, 1e308;  // the update 1e308 + 1e308 overflows
  const auto gepp = gauss_elimination<Eigen::Dynamic>(A, Eigen::VectorXd::Ones(2));
  CHECK(gepp.status == Status::non_finite);
}

TEMPLATE_TEST_CASE_SIG("Fixed-size GEPP agrees with the dynamic-size one", "[gepp][fixed]", ((int N), N), 2, 8, 10) {
  const GeneratedSystem system = generate_system("random", N, 42);
  const Matrix<N> A = system.A;
  const Vector<N> b = system.b;
  const LinearResult<N> fixed = gauss_elimination<N>(A, b);
  const auto dynamic = gauss_elimination<Eigen::Dynamic>(system.A, system.b);
  REQUIRE(fixed.status == Status::converged);
  CHECK(relative_difference(fixed.x, dynamic.x) <= agreement_tolerance(system.A, fixed.growth_factor));
  CHECK(fixed.growth_factor == Approx(dynamic.growth_factor).epsilon(1e-12));
}

namespace {
struct EventCounter : GaussElimination<Eigen::Dynamic>::Observer {
  int swaps = 0, eliminations = 0, substitutions = 0;
  StepControl on_step(const GaussElimination<Eigen::Dynamic>&, const EliminationRecord& record) override {
    if (record.event == EliminationEvent::row_swap) ++swaps;
    if (record.event == EliminationEvent::elimination) ++eliminations;
    if (record.event == EliminationEvent::back_substitution) ++substitutions;
    return StepControl::proceed;
  }
};
}  // namespace

TEST_CASE("The stepper: one step per pivot column, then one per unknown", "[gepp][stepper]") {
  const GeneratedSystem system = generate_system("gs-diverge", 3);
  GaussElimination<Eigen::Dynamic> stepper;
  EventCounter counter;
  stepper.set_observer(&counter);
  stepper.start(system.A, system.b);
  int steps = 0;
  while (stepper.step()) ++steps;
  CHECK(steps + 1 == 6);  // the sixth step ends the solve
  CHECK(counter.eliminations == 3);
  CHECK(counter.substitutions == 3);
  CHECK(counter.swaps == 2);  // column 1 takes row 3 (the 4); column 2 takes row 3 (1.5 > 0)
  // After column 1 the largest entry, 4, was brought to the top.
  stepper.start(system.A, system.b);
  stepper.step();
  CHECK(stepper.reduced_matrix()(0, 0) == 4.0);
  CHECK(stepper.reduced_matrix()(1, 0) == 0.0);
  CHECK(stepper.reduced_matrix()(2, 0) == 0.0);
}

TEST_CASE("GEPP rejects bad input with a message naming it", "[gepp][bad-input]") {
  using Catch::Matchers::Contains;
  GaussElimination<Eigen::Dynamic> gepp;
  CHECK_THROWS_WITH(gepp.solve(Eigen::MatrixXd::Ones(2, 3), Eigen::VectorXd::Ones(2)), Contains("square"));
  CHECK_THROWS_WITH(gepp.solve(Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Ones(2)), Contains("2 entries"));
  Eigen::MatrixXd with_nan = Eigen::MatrixXd::Identity(2, 2);
  with_nan(1, 0) = std::nan("");
  CHECK_THROWS_WITH(gepp.solve(with_nan, Eigen::VectorXd::Ones(2)), Contains("non-finite") && Contains("row 2"));
  GaussEliminationOptions negative;
  negative.relative_pivot_tolerance = -1.0;
  CHECK_THROWS_AS(GaussElimination<Eigen::Dynamic>(negative), std::invalid_argument);
}

TEMPLATE_TEST_CASE_SIG("Newton's GEPP path (solve_prechecked) gives solve()'s x, without the diagnostics",
                       "[gepp][prechecked]", ((int N), N), 2, 8, 10) {
  const GeneratedSystem system = generate_system("random", N, 7);
  const Matrix<N> A = system.A;
  const Vector<N> b = system.b;
  GaussElimination<N> elimination;
  const LinearResult<N> prechecked = elimination.solve_prechecked(A, b);
  const LinearResult<N> checked = elimination.solve(A, b);  // the same object: diagnostics are back
  REQUIRE(prechecked.status == Status::converged);
  CHECK(prechecked.x == checked.x);  // the same arithmetic, bit for bit
  CHECK(prechecked.iterations == checked.iterations);
  CHECK(std::isnan(prechecked.residual_norm));
  CHECK(std::isnan(prechecked.growth_factor));
  CHECK(std::isfinite(checked.growth_factor));
  CHECK(checked.residual_norm <= 10 * N * eps * A.cwiseAbs().maxCoeff() * checked.x.cwiseAbs().maxCoeff());

  Matrix<N> singular = A;
  singular.row(N - 1) = singular.row(0);
  const LinearResult<N> failed = elimination.solve_prechecked(singular, b);
  CHECK(failed.status == Status::singular);
  CHECK(failed.x.array().isNaN().all());
}

TEST_CASE("all_finite: false for a NaN or an infinity anywhere, true for huge finite values", "[input-checks]") {
  Eigen::Matrix<double, 8, 8> A = Eigen::Matrix<double, 8, 8>::Constant(1e308);  // its sum would overflow
  CHECK(all_finite(A));
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    for (int at : {0, 27, 63}) {
      Eigen::Matrix<double, 8, 8> B = A;
      B(at % 8, at / 8) = bad;
      INFO("value " << bad << " at " << at);
      CHECK_FALSE(all_finite(B));
    }
  }
  CHECK(all_finite(Eigen::VectorXd::Zero(3)));
  CHECK_FALSE(all_finite(Eigen::Vector2d(1.0, -INFINITY)));
}
