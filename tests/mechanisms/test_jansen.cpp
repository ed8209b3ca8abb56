#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/autodiff_system.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/newton.hpp"

using namespace numlab;
using namespace numlab::mechanisms;

namespace {
constexpr double degrees = std::numbers::pi / 180.0;

nonlinear::NewtonOptions tight() {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-10;
  return options;
}

// Seed 001's closure on AutoDiff scalars too, so its hand-written Jacobian can be checked exactly.
class Jansen10Differentiable final : public nonlinear::TemplatedResidual<Jansen10Differentiable> {
 public:
  explicit Jansen10Differentiable(double crank) : closure_(crank) {}
  int dimension() const override { return 10; }
  template <typename T>
  void evaluate(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x, Eigen::Matrix<T, Eigen::Dynamic, 1>& f) const {
    jansen10_residual(closure_.crank_x(), closure_.crank_y(), x, f);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    Jansen10Closure::Matrix fixed;
    closure_.jacobian(Jansen10Closure::Vector(x), fixed);
    J = fixed;
  }

 private:
  Jansen10Closure closure_;
};
}  // namespace

TEST_CASE("Circle intersection: both sides, and no meeting", "[mechanisms][circles]") {
  const auto left = circle_intersection({0, 0}, 5, {8, 0}, 5, 1);
  const auto right = circle_intersection({0, 0}, 5, {8, 0}, 5, -1);
  REQUIRE(left);
  REQUIRE(right);
  CHECK(left->x() == Approx(4.0));
  CHECK(left->y() == Approx(3.0));
  CHECK(right->y() == Approx(-3.0));
  CHECK_FALSE(circle_intersection({0, 0}, 1, {8, 0}, 1, 1));  // too far apart
  CHECK_FALSE(circle_intersection({0, 0}, 1, {0, 0}, 1, 1));  // concentric
}

TEST_CASE("Newton from seed 000's estimates lands on the closed form's branch", "[mechanisms][jansen]") {
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const auto newton = nonlinear::newton_solve(closure, JansenClosure::seed_estimates(), tight());
  REQUIRE(newton.status == Status::converged);
  const JansenLeg leg;
  const JansenJoints from_newton = leg.joints(JansenClosure::seed_crank_angle, newton.x);
  const auto closed = leg.closed_form_joints(JansenClosure::seed_crank_angle);
  REQUIRE(closed);
  for (int j = 0; j < jansen_joint_count; ++j) {
    INFO(jansen_joint_names[j]);
    CHECK((from_newton[j] - (*closed)[j]).norm() <= 1e-9);
  }
  CHECK(leg.worst_length_error(from_newton) <= 1e-9);
  CHECK(JansenLeg::triangle_orientation(from_newton) == 1);
  CHECK(leg.foot_angle() == Approx(1.729556).epsilon(1e-6));  // seed 000 eq 21
}

TEST_CASE("Over a whole turn every solver keeps the branch and agrees with the closed form to 1e-8",
          "[mechanisms][jansen][sweep]") {
  for (const JansenModel model : {JansenModel::eight_equations, JansenModel::ten_equations}) {
    for (const std::string& solver_name : jansen_solver_names()) {
      const auto solver = make_jansen_solver(model, solver_name, "gepp", tight());
      const JansenSweep sweep = crank_sweep(model, *solver, 0.0, 359.0, 1.0);
      INFO((model == JansenModel::eight_equations ? "jansen " : "jansen10 ") << solver_name);
      REQUIRE(sweep.status == Status::converged);
      CHECK(sweep.poses.size() == 360);
      CHECK(sweep.walk_in_poses == 90);  // from 1.57 rad (89.95 deg) down to 0 in 1-degree steps
      CHECK(sweep.worst_closed_form_distance <= 1e-8);
      CHECK(sweep.worst_length_error <= 1e-8);
      CHECK(sweep.orientation_kept);
    }
  }
}

TEST_CASE("Every linear method inside full Newton gives the same sweep", "[mechanisms][jansen][sweep]") {
  for (const std::string linear : {"gauss-seidel", "gsl-lu", "eigen-lu"}) {
    nonlinear::NewtonOptions options = tight();
    const auto solver = make_jansen_solver(JansenModel::eight_equations, "full", linear, options);
    const JansenSweep sweep = crank_sweep(JansenModel::eight_equations, *solver, 0.0, 359.0, 10.0);
    INFO(linear);
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.worst_closed_form_distance <= 1e-8);
  }
}

TEST_CASE("The 8- and 10-equation models give the same joints", "[mechanisms][jansen10]") {
  const auto eight = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", tight());
  const auto ten = make_jansen_solver(JansenModel::ten_equations, "full", "gepp", tight());
  const JansenSweep a = crank_sweep(JansenModel::eight_equations, *eight, 0.0, 350.0, 10.0);
  const JansenSweep b = crank_sweep(JansenModel::ten_equations, *ten, 0.0, 350.0, 10.0);
  REQUIRE(a.poses.size() == b.poses.size());
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    for (int j = 0; j < jansen_joint_count; ++j) CHECK((a.poses[i].joints[j] - b.poses[i].joints[j]).norm() <= 1e-8);
  }
}

TEST_CASE("Hand-written Jacobians of both Jansen models are right", "[mechanisms][jacobian-check]") {
  const Eigen::VectorXd ten = jansen_seed_estimates(JansenModel::ten_equations, JansenLeg());
  const nonlinear::JacobianCheck check10 = nonlinear::check_jacobian(Jansen10Differentiable(0.9), ten);
  INFO(nonlinear::describe_worst_entry(check10));
  CHECK(check10.worst_error <= 1e-13);
  const JansenClosure eight(0.9);
  const nonlinear::JacobianCheck check8 =
      nonlinear::check_jacobian(nonlinear::AsDynamicSystem(eight), Eigen::VectorXd(JansenClosure::seed_estimates()));
  CHECK(check8.agrees);
}

TEST_CASE("Sweeps start anywhere, step backwards, and refuse a step that points away", "[mechanisms][sweep]") {
  const auto solver = make_jansen_solver(JansenModel::eight_equations, "sequential", "gepp", tight());
  const JansenSweep backwards = crank_sweep(JansenModel::eight_equations, *solver, 200.0, 100.0, -25.0);
  REQUIRE(backwards.status == Status::converged);
  REQUIRE(backwards.poses.size() == 5);
  CHECK(backwards.poses.front().crank_deg == 200.0);
  CHECK(backwards.poses.back().crank_deg == 100.0);
  CHECK(backwards.worst_closed_form_distance <= 1e-8);
  const JansenSweep one = crank_sweep(JansenModel::eight_equations, *solver, 45.0, 45.0, 1.0);
  CHECK(one.poses.size() == 1);
  CHECK_THROWS_AS(crank_sweep(JansenModel::eight_equations, *solver, 0.0, 10.0, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(crank_sweep(JansenModel::eight_equations, *solver, 0.0, 10.0, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(make_jansen_solver(JansenModel::eight_equations, "bisection", "gepp", tight()), std::invalid_argument);
}

TEST_CASE("Foot velocity from one extra solve agrees with finite differences of the closed form",
          "[mechanisms][velocity]") {
  const JansenLeg leg;
  const auto solver = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", tight());
  const JansenSweep sweep = crank_sweep(JansenModel::eight_equations, *solver, 0.0, 350.0, 10.0);
  REQUIRE(sweep.status == Status::converged);
  const std::size_t F = static_cast<std::size_t>(JansenJoint::F);
  double fastest = 0.0, slowest = 1e300;
  for (const JansenPose& pose : sweep.poses) {
    const double crank = pose.crank_deg * degrees;
    const JansenRates rates = leg.rates(crank, JansenAngles(pose.angles));
    REQUIRE(rates.status == Status::converged);
    // Central difference of the exact foot position, h = 1e-5 rad: error ~ h^2 |F'''| ~ 1e-8.
    const double h = 1e-5;
    const auto ahead = leg.closed_form_joints(crank + h), behind = leg.closed_form_joints(crank - h);
    REQUIRE(ahead);
    REQUIRE(behind);
    const Eigen::Vector2d difference = ((*ahead)[F] - (*behind)[F]) / (2.0 * h);
    INFO("crank " << pose.crank_deg);
    CHECK((rates.foot_velocity - difference).norm() <= 1e-6 * std::max(1.0, difference.norm()));
    fastest = std::max(fastest, rates.foot_speed);
    slowest = std::min(slowest, rates.foot_speed);
  }
  CHECK(fastest > 2.0 * slowest);  // a walking foot: slow on the ground, fast in the air
}
