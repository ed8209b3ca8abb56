#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/anchored_sincos.hpp"
#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/sine_sources.hpp"
#include "numlab/mechanisms/sweep_observer.hpp"
#include "numlab/nonlinear/autodiff_system.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/newton.hpp"

using namespace numlab;
using namespace numlab::mechanisms;

namespace {

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
      CHECK(sweep.walk_in_poses == 18);  // from 1.57 rad (89.95 deg) down to 0 in the walk-in's 5-degree steps
      CHECK(sweep.closed_form_verified);
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

TEST_CASE("The Jansen closures on the sine table agree with the textbook ones (std::sin) to a few ulp",
          "[mechanisms][jansen][sines]") {
  const double eps = std::numeric_limits<double>::epsilon();
  std::mt19937 random(15);
  std::uniform_real_distribution<double> angle(-7.0, 7.0);
  double worst8 = 0.0, worst10 = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const double crank = angle(random);
    const JansenClosure library8(crank);
    const JansenClosureOf<TableSines> table8(crank);
    JansenClosure::Vector theta8, f8, g8;
    JansenClosure::Matrix J8, K8;
    for (int k = 0; k < 8; ++k) theta8(k) = angle(random);
    library8.residual_and_jacobian(theta8, f8, J8);
    table8.residual_and_jacobian(theta8, g8, K8);
    worst8 = std::max({worst8, (f8 - g8).cwiseAbs().maxCoeff(), (J8 - K8).cwiseAbs().maxCoeff()});

    const Jansen10Closure library10(crank);
    const Jansen10ClosureOf<TableSines> table10(crank);
    Jansen10Closure::Vector theta10, f10, g10;
    Jansen10Closure::Matrix J10, K10;
    for (int k = 0; k < 10; ++k) theta10(k) = angle(random);
    library10.residual_and_jacobian(theta10, f10, J10);
    table10.residual_and_jacobian(theta10, g10, K10);
    worst10 = std::max({worst10, (f10 - g10).cwiseAbs().maxCoeff(), (J10 - K10).cwiseAbs().maxCoeff()});
  }
  // Each term is a length (at most 65.7) times a sine within 2 ulp, summed over at most six terms.
  CHECK(worst8 <= 2.0 * eps * 400.0);
  CHECK(worst10 <= 2.0 * eps * 400.0);
  CHECK(worst8 > 0.0);  // the table is in use
  CHECK(worst10 > 0.0);
}

TEST_CASE("Evaluating a closure changes nothing: the same point gives the same bits whatever came between",
          "[mechanisms][jansen][sines]") {
  // A cache in the closure would make f at theta depend on the evaluations before: reached by a
  // Newton correction from a nearby angle, theta's sines take another path than from the table.
  const JansenClosureOf<TableSines> eight(0.4);
  const Jansen10ClosureOf<TableSines> ten(0.4);
  const JansenClosure::Vector theta8 = JansenClosure::seed_estimates();
  const Jansen10Closure::Vector theta10 = jansen_seed_estimates(JansenModel::ten_equations, JansenLeg());
  JansenClosure::Vector f8, first8;
  JansenClosure::Matrix J8, first_J8;
  Jansen10Closure::Vector f10, first10;
  Jansen10Closure::Matrix J10, first_J10;
  eight.residual_and_jacobian(theta8, first8, first_J8);
  ten.residual_and_jacobian(theta10, first10, first_J10);
  // Such a cache (AnchoredSinCos, DyadNewton's) does give other bits after this sequence.
  AnchoredSinCos<8> cache;
  JansenClosure::Vector c, s, first_c, first_s;
  cache.evaluate(theta8, first_c, first_s);
  bool cache_differs = false;
  for (const double nudge : {3e-7, -5e-7, 1e-9}) {
    for (const double step : {0.25, nudge, 0.0}) {  // far away, a Newton correction away, back at theta
      eight.residual_and_jacobian(theta8 + JansenClosure::Vector::Constant(step), f8, J8);
      ten.residual_and_jacobian(theta10 + Jansen10Closure::Vector::Constant(step), f10, J10);
      cache.evaluate(theta8 + JansenClosure::Vector::Constant(step), c, s);
    }
    INFO("back from a nudge of " << nudge);
    CHECK(f8 == first8);
    CHECK(J8 == first_J8);
    CHECK(f10 == first10);
    CHECK(J10 == first_J10);
    cache_differs = cache_differs || c != first_c || s != first_s;
  }
  CHECK(cache_differs);
}

namespace {

// The Jansen sweeps' honesty: a bounded walk-in whatever the angle or the sweep's step, and a
// converged status (and "branch kept") only when the closed form agrees within what the
// tolerance and the conditioning justify (closed_form_bound.hpp).

// Counts every pose solve a sweep attempts: the walk-in's cost, without a clock.
struct AttemptCounter final : SweepObserver<JansenSweepStepper> {
  int attempts = 0;
  StepControl on_step(const JansenSweepStepper&, const SweepPoseRecord&) override { ++attempts; return StepControl::proceed; }
};

nonlinear::NewtonOptions with_tolerance(double tolerance) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = tolerance;
  return options;
}

}  // namespace

TEST_CASE("The walk-in is bounded: whole turns are skipped, and its step is its own", "[mechanisms][sweep][honesty]") {
  for (const JansenModel model : {JansenModel::eight_equations, JansenModel::ten_equations}) {
    const auto solver = make_jansen_solver(model, "full", "gepp", {});
    INFO((model == JansenModel::eight_equations ? "jansen" : "jansen10"));
    // 1e9 deg = 2777777 turns + 280 deg: the walk goes to -80 deg (the same pose), 170 deg from
    // the seed's 89.95, in 5-degree steps: 34 poses, whatever the angle's size.
    AttemptCounter far_counter;
    const JansenSweep far = crank_sweep(model, *solver, 1e9, 1e9, 1.0, {}, &far_counter);
    REQUIRE(far.status == Status::converged);
    REQUIRE(far.poses.size() == 1);
    CHECK(far.poses[0].crank_deg == 1e9);  // the pose keeps the requested angle
    CHECK(far.walk_in_poses == 34);
    CHECK(far_counter.attempts <= 1 + 34 + 1);  // seed, walk, the pose: no retry needed
    // The same pose, bit for bit, as at 280 deg (and as at 280 - 360 = -80).
    AttemptCounter near_counter;
    const JansenSweep near = crank_sweep(model, *solver, 280.0, 280.0, 1.0, {}, &near_counter);
    REQUIRE(near.status == Status::converged);
    CHECK(near.walk_in_poses == far.walk_in_poses);
    CHECK(near_counter.attempts == far_counter.attempts);
    CHECK(far.poses[0].angles == near.poses[0].angles);
    CHECK(far.poses[0].closed_form_distance <= 1e-8);
    // An angle beyond any count of turns a double can hold exactly still ends, at its own pose.
    const JansenSweep huge = crank_sweep(model, *solver, 1e300, 1e300, 1.0);
    CHECK(huge.walk_in_poses <= 36);
    CHECK(huge.status == Status::converged);
    CHECK(huge.worst_closed_form_distance <= 1e-8);

    // A tiny sweep step no longer sets the walk's: 0:1e-6:1e-6 walks 89.95 -> 0 in 18 poses.
    AttemptCounter tiny_counter;
    const JansenSweep tiny = crank_sweep(model, *solver, 0.0, 1e-6, 1e-6, {}, &tiny_counter);
    REQUIRE(tiny.status == Status::converged);
    CHECK(tiny.poses.size() == 2);
    CHECK(tiny.walk_in_poses == 18);
    CHECK(tiny_counter.attempts <= 1 + 18 + 2);
  }
  // Whole turns only: the same angle's poses agree with the reduction (fmod is exact).
  CHECK(nearest_turn(1e9, 89.95) == -80.0);
  CHECK(nearest_turn(30.0, 89.95) == 30.0);
  CHECK(crank_radians(725.0) == crank_radians(5.0));
  // A sweep of more poses than max_sweep_poses is refused (its count would not fit an int).
  const auto solver = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", {});
  CHECK_THROWS_WITH(crank_sweep(JansenModel::eight_equations, *solver, 0.0, 1e9, 1e-6),
                    Catch::Matchers::Contains("more than 1000000 poses"));
}

TEST_CASE("Loose tolerances: a sweep is converged and its branch kept only when the closed form agrees within its bound",
          "[mechanisms][sweep][honesty]") {
  for (const JansenModel model : {JansenModel::eight_equations, JansenModel::ten_equations}) {
    for (const std::string solver_name : {"full", "sequential", "gsl-hybridsj"}) {
      for (const double tolerance : {1e10, 10.0, 1.0, 1e-2, 1e-4}) {
        INFO((model == JansenModel::eight_equations ? "jansen " : "jansen10 ") << solver_name << " tol " << tolerance);
        const auto solver = make_jansen_solver(model, solver_name, "gepp", with_tolerance(tolerance));
        const JansenSweep sweep = crank_sweep(model, *solver, 0.0, 350.0, 10.0);
        // Consistency: converged exactly when every pose is verified (given that every pose solved);
        // the branch is never said kept while the closed form disagrees.
        if (sweep.poses.size() == 36) CHECK((sweep.status == Status::converged) == sweep.closed_form_verified);
        if (sweep.orientation_kept) CHECK(sweep.closed_form_verified);
        if (sweep.status == Status::converged) {
          for (const JansenPose& pose : sweep.poses) CHECK(pose.closed_form_distance <= pose.closed_form_bound);
          CHECK(sweep.worst_closed_form_bound <= 7.5);  // half the crank
        }
      }
      // The issue's case: --crank 30 --tol 1e10 (Newton accepts the seed's estimates unmoved).
      const auto lax = make_jansen_solver(model, solver_name, "gepp", with_tolerance(1e10));
      const JansenSweep issue = crank_sweep(model, *lax, 30.0, 30.0, 1.0);
      CHECK(issue.status != Status::converged);
      CHECK_FALSE(issue.orientation_kept);
      CHECK_FALSE(issue.closed_form_verified);
      // The residual left (0.68) justifies no distance below half the crank.
      CHECK(issue.worst_closed_form_bound > 7.5);
    }
  }
}
