// The hand-written trust-region dogleg Newton (numlab/nonlinear/dogleg.hpp): on a linear system it
// is one Newton step; on Rosenbrock it reaches the known root from all three starts; on every
// MINPACK case its "converged" is backed by an independent residual evaluation.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <limits>

#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/minpack_cases.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

namespace {

// f(x) = A x - b.
class LinearSystem final : public DynamicSystem {
 public:
  LinearSystem(Eigen::MatrixXd A, Eigen::VectorXd b) : A_(std::move(A)), b_(std::move(b)) {}
  int dimension() const override { return static_cast<int>(b_.size()); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override { f = A_ * x - b_; }
  void jacobian(const Eigen::VectorXd&, Eigen::MatrixXd& J) const override { J = A_; }

 private:
  Eigen::MatrixXd A_;
  Eigen::VectorXd b_;
};

}  // namespace

TEST_CASE("dogleg on a linear system: the Newton step fits the first region and solves it", "[dogleg]") {
  Eigen::MatrixXd A(3, 3);
  A << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  const Eigen::VectorXd b(Eigen::Vector3d(1, 2, 3));
  const auto result = dogleg_solve(LinearSystem(A, b), Eigen::VectorXd::Zero(3));
  REQUIRE(result.status == Status::converged);
  CHECK(result.iterations == 1);
  const Eigen::VectorXd exact = A.partialPivLu().solve(b);
  const double kappa = A.norm() * A.inverse().norm();
  CHECK((result.x - exact).norm() <= 10 * kappa * std::numeric_limits<double>::epsilon() * exact.norm());
}

TEST_CASE("dogleg reaches Rosenbrock's root (1, 1) from x0, 10 x0 and 100 x0", "[dogleg]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  REQUIRE(problem.known_root.has_value());
  NewtonOptions options;
  options.max_iterations = 300;
  for (double factor : {1.0, 10.0, 100.0}) {
    INFO("start " << factor << " x0");
    const auto result = dogleg_solve(*problem.system, factor * problem.standard_start, options);
    REQUIRE(result.status == Status::converged);
    // J(1, 1) = [[-20, 10], [-1, 0]] is well conditioned: ||x - x*|| is within a few ||f||.
    CHECK((result.x - *problem.known_root).lpNorm<Eigen::Infinity>() <= 100 * options.residual_tolerance);
  }
}

TEST_CASE("dogleg's verdict on every MINPACK case matches the residual at its answer", "[dogleg]") {
  NewtonOptions options;
  options.residual_tolerance = 1e-10;
  for (const MinpackCase& test_case : minpack_cases()) {
    INFO(case_label(test_case));
    const MinpackInstance instance = make_minpack_instance(test_case);
    options.max_iterations = 100 * (test_case.n + 1);
    const auto result = dogleg_solve(*instance.problem.system, instance.start, options);
    Eigen::VectorXd f(test_case.n);
    instance.problem.system->residual(result.x, f);
    const bool root = f.allFinite() && f.lpNorm<Eigen::Infinity>() <= options.residual_tolerance;
    CHECK(root == (result.status == Status::converged));
    CHECK(result.residual_norm == f.lpNorm<Eigen::Infinity>());
    CHECK(result.iterations <= options.max_iterations);
  }
}

TEST_CASE("dogleg refuses a start of the wrong size or not finite", "[dogleg]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  CHECK_THROWS_AS(dogleg_solve(*problem.system, Eigen::VectorXd::Zero(3)), std::invalid_argument);
  CHECK_THROWS_AS(dogleg_solve(*problem.system, Eigen::VectorXd::Constant(2, std::nan(""))), std::invalid_argument);
}
