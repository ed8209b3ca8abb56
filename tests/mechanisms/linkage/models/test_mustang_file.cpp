// mustang.toml against the hand-coded Mustang roof linkage (seed 003, mechanisms/mustang_linkage.hpp):
// the joints to 1e-9 over its range on the seed's branch, and the assembly limits (-41.42 and
// 56.45 degrees) to 0.01 degree.
//
// The seed's branch passes through a singular pose: loop 4 is a kite (|8 9| = |9 11|, |8 10| =
// |10 11|) and the hand-coded model keeps it open (P11 = P8 mirrored in the line 9-10). Where 8, 9,
// 10 line up (theta* = 43.15 deg) the mirror image is P8 itself: the two circles that place P11
// touch, and P11 changes sides of the line 10-9. The derived model's dyad "P11 from (P10, P9)"
// keeps the side its reference pose gives, so one reference pose reproduces the open kite on one
// side of theta* only: the file's (45 deg, seed 003's start) above theta*, and the same file with
// its reference moved to 0 deg below it.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

const MustangLinkage hand_coded;

// The largest distance between the file's joints (P0 ... P12) and the hand-coded closed form's.
double worst_joint_distance(const LinkageModel& model, const LinkageSweep& sweep) {
  double worst = 0.0;
  for (const LinkagePose& pose : sweep.poses) {
    const MustangClosedForm reference = hand_coded.closed_form(pose.driver * deg);
    REQUIRE(reference.status == Status::converged);
    for (int k = 0; k < mustang_joint_count; ++k) {
      const Eigen::Vector2d file_joint = joint_at(model, pose.q, mustang_joint_names[static_cast<std::size_t>(k)]);
      worst = std::max(worst, (file_joint - reference.joints[static_cast<std::size_t>(k)]).norm());
    }
  }
  return worst;
}

// Bisection on a predicate that is true at `yes` and false at `no`, to `width` degrees.
template <typename Predicate>
double bisect(double yes, double no, double width, Predicate holds) {
  while (std::abs(no - yes) > width) {
    const double middle = 0.5 * (yes + no);
    (holds(middle) ? yes : no) = middle;
  }
  return yes;
}

bool assembles(double theta_deg) { return hand_coded.closed_form(theta_deg * deg).status == Status::converged; }

// theta* from the hand-coded model alone: where P8 crosses the line P9 -> P10.
double kite_crossing() {
  const auto side = [](double theta_deg) {
    const MustangJoints p = hand_coded.closed_form(theta_deg * deg).joints;
    const Eigen::Vector2d a = p[10] - p[9], b = p[8] - p[9];
    return a.x() * b.y() - a.y() * b.x() > 0.0;
  };
  REQUIRE(side(40.0) != side(45.0));
  const bool below = side(40.0);
  return bisect(40.0, 45.0, 1e-9, [&](double t) { return side(t) == below; });
}

LinkageSolverOptions tight(const std::string& solver, const LinkageModel& model, double worst_inverse) {
  LinkageSolverOptions options{solver, "gepp", {}};
  options.newton.residual_tolerance = residual_tolerance_for(1e-9, worst_inverse, model.unknown_count());
  options.tolerance_relative_to_size = false;  // derived from the conditioning, in length units
  options.newton.max_iterations = 50;
  return options;
}

double worst_inverse_norm(const LinkageModel& model, const LinkageSweep& sweep) {
  double worst = 0.0;
  for (const auto& pose : sweep.poses) worst = std::max(worst, inverse_jacobian_norm(model, pose.driver * deg, pose.q));
  return worst;
}

}  // namespace

TEST_CASE("The hand-coded Mustang assembles on [-41.4257, 56.4540] deg: -41.42 and 56.45 to 0.01",
          "[linkage-models]") {
  const double lower = bisect(0.0, -60.0, 1e-9, assembles), upper = bisect(45.0, 70.0, 1e-9, assembles);
  INFO("closed form assembles on [" << lower << ", " << upper << "]");
  CHECK(std::abs(lower - -41.42) <= 0.01);
  CHECK(std::abs(upper - 56.45) <= 0.01);
}

TEST_CASE("mustang.toml reproduces the hand-coded joints to 1e-9 over its range, through the kite's change point",
          "[linkage-models]") {
  const double crossing = kite_crossing();
  const double lower = bisect(0.0, -60.0, 1e-9, assembles), upper = bisect(45.0, 70.0, 1e-9, assembles);
  CHECK(std::abs(crossing - 43.15) < 0.01);  // mustang_linkage.hpp's "near theta = 43.15 deg"
  // The shipped file's reference is 0 deg. Whole quarter degrees over the range: every solver
  // continues by prediction through the kite's change point (loop 4's two solutions meet there),
  // stays on the open kite, and reports the change point where the hand-coded model finds it.
  const LinkageModel model = model_file("mustang");
  const double from = std::ceil(lower * 4.0) / 4.0, to = std::floor(upper * 4.0) / 4.0;
  const LinkageSweep exact = linkage_sweep(LinkageSolver(model, {"analytic", "gepp", {}}), from, to, 0.25);
  REQUIRE(exact.status == Status::converged);
  const double worst_inverse = worst_inverse_norm(model, exact);
  for (const std::string solver : {"analytic", "sequential", "full", "gsl-hybridsj", "gsl-newton"}) {
    const LinkageSweep sweep = linkage_sweep(LinkageSolver(model, tight(solver, model, worst_inverse)), from, to, 0.25);
    INFO(solver << " over [" << from << ", " << to << "], max ||J^-1|| = " << worst_inverse);
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.branch_kept);
    CHECK(sweep.flips.empty());
    REQUIRE(sweep.change_points.size() == 1);
    REQUIRE(sweep.crossings.size() == 1);
    CHECK(std::abs(sweep.crossings[0].driver - crossing) < 1e-3);
    CHECK(sweep.change_points[0].find("two branches cross at crank 43.1") != std::string::npos);
    CHECK(worst_joint_distance(model, sweep) < 1e-9);
  }
}

TEST_CASE("mustang.toml's assembly limits, found by bisection, are the hand-coded model's to 0.01 degree",
          "[linkage-models]") {
  const double lower = bisect(0.0, -60.0, 1e-9, assembles), upper = bisect(45.0, 70.0, 1e-9, assembles);
  // The hand-coded sweep's own limits (mustang_sweep.hpp, continuation from seed 003's start).
  numlab::nonlinear::NewtonOptions newton;
  newton.residual_tolerance = 1e-12;
  newton.max_iterations = 50;
  const auto hand_solver = make_mustang_solver("analytic", "gepp", newton);
  const MustangSweep hand = mustang_sweep(*hand_solver, -60.0, 70.0, 1.0);
  REQUIRE(hand.lower.reached);
  REQUIRE(hand.upper.reached);
  CHECK(std::abs(hand.lower.last_assembled_deg - lower) <= 0.01);
  CHECK(std::abs(hand.upper.last_assembled_deg - upper) <= 0.01);

  // Each limit from a sweep that starts inside the range and runs past it, both from the shipped file.
  const LinkageModel above = model_file("mustang"), below = model_file("mustang");
  const std::array<std::string, 4> loop_joint = {"P3", "P5", "P10", "P11"};  // the dyad of loop k
  for (const std::string solver : {"analytic", "sequential", "full"}) {
    struct Leg {
      const LinkageModel& model;
      double from, to, step, exact;
      int loop;
    };
    for (const Leg& leg : {Leg{above, 44.0, 70.0, 1.0, upper, hand.upper.loop}, Leg{below, 42.0, -60.0, -1.0, lower, hand.lower.loop}}) {
      const LinkageSolver linkage(leg.model, {solver, "gepp", {}});
      const LinkageSweep sweep = linkage_sweep(linkage, leg.from, leg.to, leg.step);
      INFO(solver << " from " << leg.from << " to " << leg.to);
      CHECK(sweep.branch_kept);
      REQUIRE(sweep.limits.size() == 1);
      const LinkageLimit& limit = sweep.limits[0];
      INFO("limit " << limit.driver << " (bracket " << limit.bracket << "), closed form " << leg.exact);
      CHECK(limit.upper);
      CHECK(limit.bracket <= 0.01);
      CHECK(std::abs(limit.driver - leg.exact) <= 0.01);
      // The block that cannot close is the dyad of the loop the hand-coded sweep names.
      REQUIRE(limit.block >= 0);
      const int joint = linkage.blocks()[static_cast<std::size_t>(limit.block)].joints[0];
      CHECK(leg.model.description().joints[static_cast<std::size_t>(joint)].name ==
            loop_joint[static_cast<std::size_t>(leg.loop - 1)]);
    }
  }
}
