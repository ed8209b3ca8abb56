#include <Eigen/LU>
#include <Eigen/SVD>
#include <catch2/catch.hpp>

#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"

using namespace numlab::linalg;

namespace {
double exact_condition_1norm(const Eigen::MatrixXd& A) {
  const Eigen::MatrixXd inverse = A.fullPivLu().inverse();
  return A.cwiseAbs().colwise().sum().maxCoeff() * inverse.cwiseAbs().colwise().sum().maxCoeff();
}
}  // namespace

TEST_CASE("The condition estimate is a close lower bound of kappa_1", "[measures]") {
  for (int n = 2; n <= 30; n += 4) {
    const Eigen::MatrixXd A = random_matrix(n, static_cast<unsigned>(n));
    const double exact = exact_condition_1norm(A);
    INFO("n = " << n << ": exact " << exact << ", estimate " << condition_estimate(A));
    CHECK(condition_estimate(A) <= exact * (1 + 1e-8));
    CHECK(condition_estimate(A) >= exact / 3);
  }
  for (int n = 2; n <= 8; ++n) {
    const Eigen::MatrixXd H = hilbert_matrix(n);
    CHECK(condition_estimate(H) == Approx(exact_condition_1norm(H)).epsilon(0.5));
  }
  CHECK(std::isinf(condition_estimate(Eigen::MatrixXd::Zero(3, 3))));
}

TEST_CASE("The condition estimate does not depend on scale: 1e-320 I and 1e300 I have kappa 1", "[measures]") {
  // A subnormal 1e-320 I must not read 'condition estimate inf' nor draw a singularity warning.
  for (double scale : {1e-320, 1e-300, 1e300}) {
    INFO("scale " << scale);
    CHECK(condition_estimate(scale * Eigen::MatrixXd::Identity(2, 2)) == Approx(1.0));
  }
  const Eigen::MatrixXd A = (Eigen::MatrixXd(2, 2) << 4, 1, 2, 3).finished();
  CHECK(condition_estimate(1e-310 * A) == Approx(condition_estimate(A)).epsilon(1e-6));
}

TEST_CASE("Relative residual and forward error", "[measures]") {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3) * 2.0;
  const Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  CHECK(relative_residual(A, A * x, x) == 0.0);
  // ||b - A y|| / (||A|| ||y||) with y = (1, 1, 2), b = (2, 2, 2): 2 / (2 * 2).
  CHECK(relative_residual(A, A * x, Eigen::Vector3d(1, 1, 2)) == Approx(0.5));
  CHECK(forward_error(Eigen::Vector3d(1, 1, 1.5), x) == Approx(0.5));
  CHECK(relative_residual(A, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(3)) == 0.0);
}

TEST_CASE("Test matrices have the properties they are named for", "[test-matrices]") {
  const Eigen::MatrixXd W = wilkinson_matrix(5);
  CHECK(W(0, 0) == 1.0);
  CHECK(W(3, 1) == -1.0);
  CHECK(W(1, 3) == 0.0);
  CHECK(W(0, 4) == 1.0);
  CHECK(hilbert_matrix(4)(2, 3) == Approx(1.0 / 6.0));

  const Eigen::MatrixXd D = diagonally_dominant_matrix(20, 5);
  for (int i = 0; i < 20; ++i) {
    CHECK(std::abs(D(i, i)) > D.row(i).cwiseAbs().sum() - std::abs(D(i, i)));
  }
  for (int n = 2; n <= 12; n += 5) {
    CHECK(singular_matrix(n, 3).fullPivLu().rank() == n - 1);
  }
  for (double kappa : {1.0, 10.0, 1e6}) {
    const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(matrix_with_condition(6, kappa, 2)).singularValues();
    CHECK(sigma(0) / sigma(5) == Approx(kappa).epsilon(1e-8));
  }
}

TEST_CASE("Generated systems have the all-ones solution, and bad requests are refused", "[test-matrices][bad-input]") {
  for (const std::string& kind : generator_kinds()) {
    const GeneratedSystem system = generate_system(kind, 5);
    CHECK(system.b.isApprox(system.A * Eigen::VectorXd::Ones(system.A.rows())));
  }
  CHECK(generate_system("gs-diverge", 99).A.rows() == 3);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(generate_system("tridiagonal", 5), Contains("unknown generator 'tridiagonal'"));
  CHECK_THROWS_WITH(generate_system("random", 0), Contains("size 0"));
  CHECK_THROWS_AS(generate_system("random", max_generated_size + 1), std::invalid_argument);
  CHECK_THROWS_AS(generate_system("singular", 1), std::invalid_argument);
}
