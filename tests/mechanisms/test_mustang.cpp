// The Mustang roof linkage (seed 003): the model's invariants, sequential against full Newton,
// the closed form, the assembly limits, and the seed's method.

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"
#include "numlab/mechanisms/mustang_seed_method.hpp"
#include "numlab/mechanisms/mustang_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"

using namespace numlab;
using namespace numlab::mechanisms;

namespace {

// A sweep with Newton stopping at ||f||_inf <= 1e-12 (the CLI's default).
MustangSweep sweep_with(const std::string& solver, double start, double stop, double step) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  options.max_iterations = 50;
  const auto pose_solver = make_mustang_solver(solver, "gepp", options);
  return mustang_sweep(*pose_solver, start, stop, step);
}

// Where loop 2 stops closing, from its geometry alone: |P0 P6(theta)| = |0 5| +- |5 6|, with
// P6 = P2 + 2 (2.5) cos 20 u(theta + 20) (independent of the solvers and of the closed form).
double loop2_limit(double inside_deg, double outside_deg) {
  const double r = std::sqrt(0.5), chord = 5.0 * std::cos(20.0 * degrees);
  auto margin = [&](double deg) {
    const double x = chord * std::cos((deg + 20.0) * degrees) - r, y = 1.0 + r + chord * std::sin((deg + 20.0) * degrees);
    const double distance = std::hypot(x, y);
    return std::min(distance - (5.0 - 4.0 / 3.0), 5.0 + 4.0 / 3.0 - distance);
  };
  for (int i = 0; i < 100; ++i) {
    const double middle = 0.5 * (inside_deg + outside_deg);
    (margin(middle) >= 0.0 ? inside_deg : outside_deg) = middle;
  }
  return inside_deg;
}

// Where the closed form stops closing, by bisection between an angle inside and one outside.
MustangClosedForm closed_form_limit(double inside_deg, double outside_deg, double& limit_deg) {
  const MustangLinkage linkage;
  for (int i = 0; i < 100; ++i) {
    const double middle = 0.5 * (inside_deg + outside_deg);
    (linkage.closed_form(middle * degrees).status == Status::converged ? inside_deg : outside_deg) = middle;
  }
  limit_deg = inside_deg;
  return linkage.closed_form(outside_deg * degrees);
}
}  // namespace

TEST_CASE("Mustang: the hand-derived 8x8 Jacobian agrees with central finite differences", "[mechanisms][mustang]") {
  for (const double theta : {-30.0, 10.0, 45.0, 58.0}) {
    const MustangClosure closure(theta * degrees);
    Eigen::VectorXd x(8);
    x << 0.3, 1.2, -0.7, 2.1, 0.4, -1.3, 2.6, 0.9;
    const auto check = nonlinear::check_jacobian(nonlinear::AsDynamicSystem(closure), x);
    INFO(nonlinear::describe_worst_entry(check));
    CHECK(check.agrees);
  }
}

TEST_CASE("Mustang: the seed's start at 45 deg lands on the closed form's branch", "[mechanisms][mustang]") {
  const MustangStart start = mustang_seed_start();
  REQUIRE(start.status == Status::converged);
  const MustangLinkage linkage;
  const MustangClosedForm exact = linkage.closed_form(45.0 * degrees);
  REQUIRE(exact.status == Status::converged);
  const MustangJoints joints = linkage.joints(45.0 * degrees, start.x);
  for (int j = 0; j < mustang_joint_count; ++j) {
    INFO("P" << j);
    CHECK((joints[j] - exact.joints[j]).norm() <= 1e-10);
  }
  // Loops 1-3 converge from [pi/18, pi/2] without damping; loop 4 (near its collinear kite) does not.
  CHECK(start.loop_status[0] == Status::converged);
  CHECK(start.loop_status[1] == Status::converged);
  CHECK(start.loop_status[2] == Status::converged);
  CHECK(start.loop_status[3] != Status::converged);
  // The open kite: P11 is P8 mirrored in the line 9-10, not P8 itself.
  CHECK((joints[11] - joints[8]).norm() > 0.1);
}

TEST_CASE("Mustang: the closed form's limits: loop 2 below, loop 3 above", "[mechanisms][mustang][limits]") {
  double lower = 0.0, upper = 0.0;
  CHECK(closed_form_limit(0.0, -90.0, lower).failed_loop == 2);
  CHECK(closed_form_limit(45.0, 90.0, upper).failed_loop == 3);
  CHECK(lower == Approx(loop2_limit(0.0, -90.0)).margin(1e-9));  // loop 2's own geometry agrees
  CHECK(upper < loop2_limit(45.0, 90.0));                          // loop 3 fails before loop 2 would
}

TEST_CASE("Mustang: a wide sweep stops at both assembly limits, found to 0.01 deg, and names the loops",
          "[mechanisms][mustang][limits]") {
  const MustangSweep sweep = sweep_with("full", -90.0, 90.0, 0.5);
  CHECK(sweep.status == Status::cannot_assemble);
  REQUIRE(sweep.lower.reached);
  REQUIRE(sweep.upper.reached);
  CHECK(sweep.lower.status == Status::cannot_assemble);
  CHECK(sweep.upper.status == Status::cannot_assemble);
  CHECK(sweep.lower.loop == 2);
  CHECK(sweep.upper.loop == 3);
  double lower = 0.0, upper = 0.0;
  closed_form_limit(0.0, -90.0, lower);
  closed_form_limit(45.0, 90.0, upper);
  INFO("limits " << sweep.lower.last_assembled_deg << " and " << sweep.upper.last_assembled_deg << "; closed form: "
                 << lower << " and " << upper);
  // The last angle that assembled lies inside the range and within 0.01 deg of its end.
  CHECK(sweep.lower.last_assembled_deg >= lower);
  CHECK(sweep.lower.last_assembled_deg - lower <= 0.01);
  CHECK(sweep.upper.last_assembled_deg <= upper);
  CHECK(upper - sweep.upper.last_assembled_deg <= 0.01);
  CHECK(std::abs(sweep.lower.failed_deg - sweep.lower.last_assembled_deg) <= 0.01);
  // Every requested angle inside the range, and only those, was solved.
  REQUIRE_FALSE(sweep.poses.empty());
  CHECK(sweep.poses.front().crank_deg == std::ceil(lower * 2.0) / 2.0);
  CHECK(sweep.poses.back().crank_deg == std::floor(upper * 2.0) / 2.0);
  CHECK(sweep.poses.size() == static_cast<std::size_t>((sweep.poses.back().crank_deg - sweep.poses.front().crank_deg) * 2.0) + 1);
}

TEST_CASE("Mustang: at every pose the links, rigid bodies and fixed points hold and the branch is kept",
          "[mechanisms][mustang][invariants]") {
  for (const std::string solver : {"full", "sequential"}) {
    INFO(solver);
    const MustangSweep sweep = sweep_with(solver, -90.0, 90.0, 0.5);
    REQUIRE(sweep.poses.size() > 150);
    for (const MustangPose& pose : sweep.poses) {
      INFO("theta = " << pose.crank_deg << ", kappa(J) = " << pose.condition);
      // Newton stops at ||f|| <= 1e-12, so a joint is off by about kappa(J) 1e-12 at most.
      const double tolerance = std::max(1e-11, 1e-11 * pose.condition);
      CHECK(pose.length_error <= tolerance);
      CHECK(pose.rigid_error <= tolerance);
      CHECK(pose.fixed_error == 0.0);
      CHECK(pose.closed_form_distance <= tolerance);  // the branch kept, through the kite's crossing at 43.15
    }
    CHECK(sweep.branch_kept);
  }
}

TEST_CASE("Mustang: sequential (four 2x2 loops) and full 8x8 Newton agree to 1e-9", "[mechanisms][mustang]") {
  const MustangSweep full = sweep_with("full", -41.0, 56.0, 1.0);
  const MustangSweep sequential = sweep_with("sequential", -41.0, 56.0, 1.0);
  const MustangSweep gsl = sweep_with("gsl-hybridsj", -41.0, 56.0, 1.0);
  REQUIRE(full.poses.size() == 98);
  REQUIRE(sequential.poses.size() == 98);
  REQUIRE(gsl.poses.size() == 98);
  for (std::size_t i = 0; i < full.poses.size(); ++i) {
    INFO("theta = " << full.poses[i].crank_deg);
    CHECK((full.poses[i].angles - sequential.poses[i].angles).lpNorm<Eigen::Infinity>() <= 1e-9);
    CHECK((full.poses[i].angles - gsl.poses[i].angles).lpNorm<Eigen::Infinity>() <= 1e-9);
  }
}

TEST_CASE("Mustang: the sequential solver itself fails in the loop that cannot close", "[mechanisms][mustang][limits]") {
  const MustangSweep sweep = sweep_with("sequential", -60.0, 70.0, 1.0);
  REQUIRE(sweep.upper.reached);
  REQUIRE(sweep.lower.reached);
  CHECK(sweep.upper.loop == 3);
  CHECK(sweep.upper.solver_loop == 3);
  CHECK(sweep.lower.loop == 2);
  CHECK(sweep.lower.solver_loop == 2);
}

TEST_CASE("Mustang: an angle outside the range is cannot_assemble, with no pose", "[mechanisms][mustang][limits]") {
  for (const double crank : {80.0, -60.0, 180.0}) {
    INFO(crank);
    const MustangSweep sweep = sweep_with("full", crank, crank, 1.0);
    CHECK(sweep.status == Status::cannot_assemble);
    CHECK(sweep.poses.empty());
  }
  const MustangSweep inside = sweep_with("full", 10.0, 10.0, 1.0);
  CHECK(inside.status == Status::converged);
  CHECK(inside.poses.size() == 1);
}

TEST_CASE("Mustang: seed 003's method as written fails inside the range, and fixed it solves every pose",
          "[mechanisms][mustang][seed]") {
  const MustangLinkage linkage;
  int failures = 0, wrong = 0;
  for (double deg = -41.0; deg <= 56.0; deg += 1.0) {
    const SeedMethodPose pose = seed_method_pose(deg * degrees, SeedMethodOptions{});
    if (pose.status != Status::converged) ++failures;
    else if (pose.residual_norm > 1e-2) ++wrong;  // its test passed, its equations do not hold
  }
  CHECK(failures + wrong > 0);
  // Every error fixed, and each pose started from the last one: every pose solves.
  SeedMethodOptions fixed{false, false, false, false, 1e-12, 100};
  MustangAngles x = mustang_seed_start().x;
  for (double deg = 45.0; deg <= 56.0; deg += 1.0) {
    const SeedMethodPose pose = seed_method_pose(deg * degrees, fixed, x);
    INFO(deg);
    REQUIRE(pose.status == Status::converged);
    CHECK(pose.residual_norm <= 1e-11);
    x = pose.x;
  }
}

TEST_CASE("Mustang: near loop 4's crossing (43.15 deg) a single angle stays on the open kite", "[mechanisms][mustang]") {
  const MustangLinkage linkage;
  for (const std::string solver : {"full", "sequential"}) {
    for (const double crank : {43.14, 43.15, 43.1533, 43.16, 30.0}) {
      INFO(solver << " at " << crank);
      const MustangSweep sweep = sweep_with(solver, crank, crank, 1.0);
      REQUIRE(sweep.status == Status::converged);
      REQUIRE(sweep.poses.size() == 1);
      const MustangPose& pose = sweep.poses[0];
      CHECK(pose.closed_form_distance <= std::max(1e-11, 1e-11 * pose.condition));
      CHECK(MustangLinkage::on_seed_branch(pose.joints));
    }
  }
  // The folded kite (P11 on P8) closes loop 4 too, and is not the seed's branch.
  MustangJoints folded = linkage.closed_form(43.0 * degrees).joints;
  CHECK(MustangLinkage::on_seed_branch(folded));
  folded[11] = folded[8];
  CHECK(std::abs((folded[11] - folded[9]).norm() - 1.0) <= 1e-12);
  CHECK(std::abs((folded[11] - folded[10]).norm() - 4.0 / 3.0) <= 1e-12);
  CHECK_FALSE(MustangLinkage::on_seed_branch(folded));
}

TEST_CASE("Mustang: the seed's loop-3 Jacobian row is what stops its Newton, from the seed's own guess",
          "[mechanisms][mustang][seed]") {
  for (const double deg : {35.0, 45.0, 55.0}) {
    INFO(deg);
    SeedMethodOptions as_written;
    const SeedMethodPose seed = seed_method_pose(deg * degrees, as_written);
    CHECK(seed.loops[2].status == Status::max_iterations);  // the flipped row: no convergence
    SeedMethodOptions corrected = as_written;
    corrected.seed_jacobian = false;
    corrected.sum_test = false;
    const SeedMethodPose fixed = seed_method_pose(deg * degrees, corrected);
    CHECK(fixed.loops[2].status == Status::converged);      // the same guess, the right Jacobian
    CHECK(fixed.loops[2].residual_norm <= 1e-3);
  }
}

TEST_CASE("Mustang gsl-<type> pose solver: one workspace for every pose, the same results as a fresh one",
          "[mechanisms][mustang][solvers]") {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  options.max_iterations = 50;
  for (const std::string type : {"hybrids", "newton"}) {
    INFO(type);
    const auto reused = make_mustang_solver("gsl-" + type, "gepp", options);
    MustangAngles x = mustang_seed_start().x;
    for (double deg = 45.0; deg <= 55.0; deg += 2.0) {
      // Reference: GSL's own solve with a workspace allocated for this pose alone.
      const MustangClosure closure(deg * degrees);
      const nonlinear::AsDynamicSystem<MustangClosure> system(closure);
      const auto fresh = nonlinear::gsl_multiroot_solve(system, Eigen::VectorXd(x), type, options);
      const PoseOutcome outcome = reused->solve(deg * degrees, x);
      INFO(deg);
      REQUIRE(outcome.status == Status::converged);
      CHECK(outcome.iterations == fresh.iterations);
      CHECK(outcome.residual_norm == fresh.residual_norm);
      CHECK(x == MustangAngles(fresh.x));
    }
  }
}

namespace {

// Counts every pose solve a Mustang sweep attempts: the walk's cost, without a clock.
struct MustangAttempts final : SweepObserver<MustangSweepStepper> {
  int attempts = 0;
  StepControl on_step(const MustangSweepStepper&, const SweepPoseRecord&) override { ++attempts; return StepControl::proceed; }
};

}  // namespace

TEST_CASE("Mustang: the walk to the first angle is bounded, whole turns skipped, its step its own",
          "[mechanisms][mustang][honesty]") {
  const auto solver = make_mustang_solver("full", "gepp", {});
  // 30 deg plus 2777777 turns: marched to at 30 deg (15 steps of 1 deg from 45), the same pose.
  const double far_angle = 30.0 + 360.0 * 2777777.0;
  MustangAttempts far_count, near_count;
  const MustangSweep far = mustang_sweep(*solver, far_angle, far_angle, 1.0, {}, &far_count);
  const MustangSweep near = mustang_sweep(*solver, 30.0, 30.0, 1.0, {}, &near_count);
  REQUIRE(far.status == Status::converged);
  REQUIRE(far.poses.size() == 1);
  CHECK(far.poses[0].crank_deg == far_angle);  // the pose keeps the requested angle
  CHECK(far.poses[0].angles == near.poses[0].angles);
  CHECK(far_count.attempts == near_count.attempts);
  CHECK(far_count.attempts <= 16);
  CHECK(far.branch_kept);
  // 1e9 deg is 280 deg, i.e. -80: beyond the lower limit, found within a bounded number of solves.
  MustangAttempts limit_count;
  const MustangSweep beyond = mustang_sweep(*solver, 1e9, 1e9, 1.0, {}, &limit_count);
  CHECK(beyond.status == Status::cannot_assemble);
  CHECK(beyond.poses.empty());
  CHECK(limit_count.attempts <= 200);
  // A tiny requested step no longer sets the walk's: 45 -> 1e-6 in steps of 1 deg, then 0.
  MustangAttempts tiny_count;
  const MustangSweep tiny = mustang_sweep(*solver, 0.0, 1e-6, 1e-6, {}, &tiny_count);
  REQUIRE(tiny.status == Status::converged);
  CHECK(tiny.poses.size() == 2);
  CHECK(tiny_count.attempts <= 46 + 2);
  CHECK_THROWS_AS(mustang_sweep(*solver, 0.0, 1e9, 1e-6), std::invalid_argument);
}

TEST_CASE("Mustang: loose tolerances are converged with the branch kept only when the closed form agrees within its bound",
          "[mechanisms][mustang][honesty]") {
  for (const std::string solver_name : {"full", "sequential"}) {
    for (const double tolerance : {1e10, 1.0, 1e-2, 1e-6, 1e-12}) {
      INFO(solver_name << " tol " << tolerance);
      nonlinear::NewtonOptions options;
      options.residual_tolerance = tolerance;
      const auto solver = make_mustang_solver(solver_name, "gepp", options);
      const MustangSweep sweep = mustang_sweep(*solver, 0.0, 50.0, 5.0);
      if (!sweep.lower.reached && !sweep.upper.reached) CHECK((sweep.status == Status::converged) == sweep.branch_kept);
      if (sweep.status == Status::converged) {
        CHECK(sweep.branch_kept);
        for (const MustangPose& pose : sweep.poses) CHECK(pose.closed_form_distance <= pose.closed_form_bound);
        CHECK(sweep.worst_closed_form_bound <= 0.5);  // half the shortest link
      }
      if (tolerance == 1e-12) CHECK(sweep.status == Status::converged);  // the default is unchanged
    }
  }
}
