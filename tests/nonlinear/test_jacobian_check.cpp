#include <catch2/catch.hpp>

#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"

using namespace numlab::nonlinear;

namespace {
// A problem whose Jacobian has one wrong entry, as a student's might: J(1,1) off by 2%.
class SlippedJacobian final : public DynamicSystem {
 public:
  explicit SlippedJacobian(std::shared_ptr<const AutoDiffSystem> system) : system_(std::move(system)) {}
  int dimension() const override { return system_->dimension(); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override { system_->residual(x, f); }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    system_->jacobian(x, J);
    J(0, 0) *= 1.02;
  }

 private:
  std::shared_ptr<const AutoDiffSystem> system_;
};
}  // namespace

TEST_CASE("Every MGH Jacobian agrees with AutoDiff, and finite differences agree with both", "[jacobian-check]") {
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    for (const Eigen::VectorXd& x : {problem.standard_start, Eigen::VectorXd(problem.standard_start * 0.7 +
                                                                             Eigen::VectorXd::Constant(problem.standard_start.size(), 0.3))}) {
      const JacobianCheck check = check_jacobian(*problem.system, x);
      INFO(name << ": " << describe_worst_entry(check));
      REQUIRE(check.autodiff.size() > 0);
      CHECK(check.worst_error <= 1e-13);                  // against AutoDiff: exact to rounding
      CHECK(check.finite_difference_agreement <= 1e-7);   // central differences: ~h^2 + eps/h
      CHECK(check.agrees);
    }
  }
}

TEST_CASE("A wrong Jacobian entry is found and named", "[jacobian-check][failure]") {
  const TestProblem problem = make_test_problem("freudenstein-roth");
  const SlippedJacobian slipped(problem.system);
  const JacobianCheck check = check_jacobian(slipped, problem.standard_start);
  CHECK_FALSE(check.agrees);
  CHECK(check.worst_row == 0);
  CHECK(check.worst_column == 0);
  CHECK(check.worst_error == Approx(0.02).epsilon(1e-6));  // J(1,1) = 1 for this problem
  CHECK_THAT(describe_worst_entry(check), Catch::Matchers::Contains("J(1,1) = 1.02"));
  CHECK_THROWS_AS(check_jacobian(slipped, problem.standard_start, -1.0), std::invalid_argument);
}
