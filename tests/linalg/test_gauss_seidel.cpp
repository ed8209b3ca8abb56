#include <catch2/catch.hpp>
#include <cmath>

#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "reference_tolerance.hpp"

using namespace numlab;
using namespace numlab::linalg;
using numlab::test::relative_difference;

namespace {
GaussSeidelOptions plain_options() {
  GaussSeidelOptions options;
  options.system = GaussSeidelOptions::System::plain;
  return options;
}

// For a converged Gauss-Seidel run stopped at ||dx|| <= tol, the error is at most about
// kappa(M) * tol (M the swept matrix); a factor 10 covers the constant.
double sweep_error_bound(double kappa_of_swept_matrix, double tolerance) { return 10.0 * kappa_of_swept_matrix * tolerance; }
}  // namespace

TEST_CASE("Plain Gauss-Seidel diverges on [[1,2,4],[2,1,2],[4,2,1]]", "[gauss-seidel][failure]") {
  const GeneratedSystem system = generate_system("gs-diverge", 3);
  const auto result = GaussSeidel<Eigen::Dynamic>(plain_options()).solve(system.A, system.b);
  CHECK(result.status == Status::diverged);
  CHECK(result.iterations < 100);          // stopped by the divergence test, not the limit
  CHECK(result.step_norm > 1e6);           // the numbers behind the status
  CHECK(std::isfinite(result.residual_norm));
}

TEST_CASE("Gauss-Seidel on the normal equations converges on the same system", "[gauss-seidel]") {
  const GeneratedSystem system = generate_system("gs-diverge", 3);
  GaussSeidelOptions options;
  options.max_iterations = 10000;
  const auto result = GaussSeidel<Eigen::Dynamic>(options).solve(system.A, system.b);
  REQUIRE(result.status == Status::converged);
  const double kappa = condition_estimate(system.A);
  CHECK(forward_error(result.x, system.exact_solution) <= sweep_error_bound(kappa * kappa, options.tolerance));
  // The residual reported is that of the original system A x = b.
  CHECK(result.residual_norm == Approx((system.b - system.A * result.x).lpNorm<Eigen::Infinity>()).margin(0));
}

TEST_CASE("Gauss-Seidel sweeps on the normal equations grow with kappa(A)^2", "[gauss-seidel][conditioning]") {
  GaussSeidelOptions options;
  options.max_iterations = 1000000;
  std::vector<int> sweeps;
  const std::vector<double> kappas = {2, 4, 8, 16, 32};
  for (double kappa : kappas) {
    const Eigen::MatrixXd A = matrix_with_condition(8, kappa, 7);
    const Eigen::VectorXd b = A * Eigen::VectorXd::Ones(8);
    const auto result = GaussSeidel<Eigen::Dynamic>(options).solve(A, b);
    INFO("kappa = " << kappa);
    REQUIRE(result.status == Status::converged);
    CHECK(forward_error(result.x, Eigen::VectorXd::Ones(8)) <= sweep_error_bound(kappa * kappa, options.tolerance));
    sweeps.push_back(result.iterations);
  }
  for (std::size_t i = 1; i < sweeps.size(); ++i) {
    INFO("sweeps " << sweeps[i - 1] << " -> " << sweeps[i]);
    CHECK(sweeps[i] > sweeps[i - 1]);
  }
  // Doubling kappa quadruples kappa^2: over 16x in kappa, expect far more than 16x the sweeps.
  CHECK(sweeps.back() > 50 * sweeps.front());
}

TEST_CASE("Gauss-Seidel agrees with GSL LU on diagonally dominant systems", "[gauss-seidel][reference]") {
  for (int n = 1; n <= 50; n += 7) {
    const GeneratedSystem system = generate_system("diag-dominant", n, static_cast<unsigned>(n));
    const auto gsl = gsl_lu_solve(system.A, system.b);
    const double kappa = condition_estimate(system.A);
    GaussSeidelOptions normal;
    normal.max_iterations = 100000;
    const auto on_normal = GaussSeidel<Eigen::Dynamic>(normal).solve(system.A, system.b);
    const auto on_plain = GaussSeidel<Eigen::Dynamic>(plain_options()).solve(system.A, system.b);
    INFO("n = " << n);
    REQUIRE(on_normal.status == Status::converged);
    REQUIRE(on_plain.status == Status::converged);
    CHECK(relative_difference(on_normal.x, gsl.x) <= sweep_error_bound(kappa * kappa, normal.tolerance));
    CHECK(relative_difference(on_plain.x, gsl.x) <= sweep_error_bound(kappa, normal.tolerance));
  }
}

TEST_CASE("The stop test uses |dx|: a sweep that only decreases x does not stop it", "[gauss-seidel][seed-bug]") {
  // Starting above the solution, every component of the first update is negative, so seed 001's
  // test all((x_new - x) < tol) would stop after one sweep, far from the answer.
  const GeneratedSystem system = generate_system("diag-dominant", 6);
  const Eigen::VectorXd above = 10.0 * Eigen::VectorXd::Ones(6);
  GaussSeidel<Eigen::Dynamic> iteration(plain_options());
  iteration.start(system.A, system.b, above);
  iteration.step();
  REQUIRE(((iteration.x() - above).array() < 0.0).all());
  CHECK(iteration.running());
  while (iteration.step()) {
  }
  CHECK(iteration.status() == Status::converged);
  CHECK(iteration.iterations() > 1);
  CHECK(forward_error(iteration.x(), system.exact_solution) < 1e-8);
}

TEST_CASE("Gauss-Seidel reports max_iterations, non_finite and singular", "[gauss-seidel][failure]") {
  const GeneratedSystem system = generate_system("hilbert", 6);
  GaussSeidelOptions few;
  few.max_iterations = 3;
  const auto limited = GaussSeidel<Eigen::Dynamic>(few).solve(system.A, system.b);
  CHECK(limited.status == Status::max_iterations);
  CHECK(limited.iterations == 3);

  // x1 = (1 - x2) / 1e-300 reaches 1e300, and the next sweep overflows.
  Eigen::MatrixXd tiny_diagonal(2, 2);
  tiny_diagonal << 1e-300, 1, 1, 1;
  const auto overflowing =
      GaussSeidel<Eigen::Dynamic>(plain_options()).solve(tiny_diagonal, Eigen::Vector2d(1, 2));
  CHECK(overflowing.status == Status::non_finite);

  Eigen::MatrixXd swap(2, 2);
  swap << 0, 1, 1, 0;
  CHECK(GaussSeidel<Eigen::Dynamic>(plain_options()).solve(swap, Eigen::Vector2d(1, 2)).status == Status::singular);
  // Its normal equations are the identity: fine.
  CHECK(GaussSeidel<Eigen::Dynamic>().solve(swap, Eigen::Vector2d(1, 2)).status == Status::converged);
}

// The normal equations' sweeps settle at a least-squares solution whether or not A x = b has one:
// on x1 + x2 = 1, x1 + x2 = 2 they settle at once (x = (1.5, 0)), and the update test passes.
TEST_CASE("Gauss-Seidel that settles on a least-squares solution of an inconsistent system is not converged",
          "[gauss-seidel][honesty]") {
  Eigen::MatrixXd A(2, 2);
  A << 1, 1, 1, 1;
  const auto inconsistent = GaussSeidel<Eigen::Dynamic>().solve(A, Eigen::Vector2d(1, 2));
  CHECK(inconsistent.status == Status::no_progress);
  CHECK(inconsistent.step_norm <= 1e-9);                       // the update test passed ...
  CHECK(inconsistent.residual_norm == Approx(0.5).margin(1e-12));  // ... but ||b - A x||_inf is half of ||b||
  CHECK(std::abs(inconsistent.x.sum() - 1.5) <= 1e-12);        // the least-squares line x1 + x2 = 1.5
  // The same singular A with a consistent b: the sweeps settle on one of its solutions, converged.
  const auto consistent = GaussSeidel<Eigen::Dynamic>().solve(A, Eigen::Vector2d(2, 2));
  CHECK(consistent.status == Status::converged);
  CHECK(consistent.residual_norm <= 1e-12);
  // Plain sweeps on the inconsistent system never settle: x2 grows by 1 a sweep.
  const auto plain = GaussSeidel<Eigen::Dynamic>(plain_options()).solve(A, Eigen::Vector2d(1, 2));
  CHECK(plain.status != Status::converged);
  // A slightly inconsistent b (backward error below sqrt(tol)) is a solution of a nearby system.
  const auto nearly = GaussSeidel<Eigen::Dynamic>().solve(A, Eigen::Vector2d(1, 1 + 1e-7));
  CHECK(nearly.status == Status::converged);
}

TEST_CASE("Fixed-size Gauss-Seidel agrees with the dynamic-size one", "[gauss-seidel][fixed]") {
  const GeneratedSystem system = generate_system("diag-dominant", 8, 3);
  GaussSeidelOptions options;
  options.max_iterations = 10000;
  const auto fixed = GaussSeidel<8>(options).solve(system.A, system.b);
  const auto dynamic = GaussSeidel<Eigen::Dynamic>(options).solve(system.A, system.b);
  REQUIRE(fixed.status == Status::converged);
  CHECK(fixed.iterations == dynamic.iterations);
  CHECK(relative_difference(fixed.x, dynamic.x) <= 1e-12);
}

TEST_CASE("Gauss-Seidel rejects bad options and input", "[gauss-seidel][bad-input]") {
  GaussSeidelOptions negative;
  negative.tolerance = -1e-9;
  CHECK_THROWS_WITH(GaussSeidel<Eigen::Dynamic>(negative), Catch::Matchers::Contains("tolerance"));
  GaussSeidelOptions zero_limit;
  zero_limit.max_iterations = 0;
  CHECK_THROWS_AS(GaussSeidel<Eigen::Dynamic>(zero_limit), std::invalid_argument);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  CHECK_THROWS_AS(GaussSeidel<Eigen::Dynamic>().solve(A, Eigen::VectorXd::Ones(3)), std::invalid_argument);
  CHECK_THROWS_AS(GaussSeidel<Eigen::Dynamic>().solve(A, Eigen::VectorXd::Ones(2), Eigen::Vector2d(std::nan(""), 0)),
                  std::invalid_argument);
}
