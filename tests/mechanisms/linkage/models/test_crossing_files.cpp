// parallelogram.toml and isosceles-slider-crank.toml: two linkages whose assembly branches cross
// (not fold) at singular poses. A sweep must follow the smooth branch through every crossing, on any
// grid (poses on the crossing, sub-steps that land on it, sweeps that start there, steps of 0.1 and
// 10 degrees, several crossings, more than one turn), with every solver; report each crossing by
// name; and take the other branch when asked (AtCrossing::switch_branch).
//
// Closed forms (crank angle t):
//   parallelogram  A = 2 (cos t, sin t), B = A + (4, 0)            crossings at 0 and 180 deg
//   isosceles      A = (cos t, sin t),   B = (2 cos t, 0)          crossings at 90 and 270 deg
//                  the other branch: B = (0, 0)
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <Eigen/SVD>
#include <cmath>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

struct CrossingModel {
  std::string name;
  std::vector<double> crossings_deg;  // within one turn
  Eigen::Vector2d (*a)(double);
  Eigen::Vector2d (*b)(double);
};

const std::vector<CrossingModel>& crossing_models() {
  static const std::vector<CrossingModel> models = {
      {"parallelogram", {0.0, 180.0}, [](double t) { return Eigen::Vector2d(2.0 * std::cos(t), 2.0 * std::sin(t)); },
       [](double t) { return Eigen::Vector2d(4.0 + 2.0 * std::cos(t), 2.0 * std::sin(t)); }},
      {"isosceles-slider-crank", {90.0, 270.0}, [](double t) { return Eigen::Vector2d(std::cos(t), std::sin(t)); },
       [](double t) { return Eigen::Vector2d(2.0 * std::cos(t), 0.0); }},
  };
  return models;
}

// The distance from a crossing angle, in degrees, over every turn.
double degrees_from_crossing(const CrossingModel& m, double driver_deg) {
  double nearest = 360.0;
  for (const double c : m.crossings_deg) nearest = std::min(nearest, std::abs(std::remainder(driver_deg - c, 360.0)));
  return nearest;
}

// The crossings strictly inside (start, stop) of a sweep, over every turn.
int crossings_inside(const CrossingModel& m, double start, double stop) {
  int count = 0;
  for (int turn = -4; turn <= 4; ++turn) {
    for (const double c : m.crossings_deg) {
      const double at = c + 360.0 * turn;
      if (at > std::min(start, stop) + 1e-9 && at < std::max(start, stop) - 1e-9) ++count;
    }
  }
  return count;
}

// How far a pose may be from the closed form, from its conditioning: to first order ||J^-1|| r, and
// at a singular pose sqrt(2 L r) (the distance rows grow as e^2 / 2L along J's null direction), r the
// residual test's bound on ||Phi||_2; ten times the smaller, and never less than rounding.
double allowed_distance(const LinkageSolver& solver, double t, const Eigen::VectorXd& q) {
  Eigen::MatrixXd J;
  solver.model().jacobian(q, t, J);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
  const double smallest = svd.singularValues()(svd.singularValues().size() - 1);
  const double r = std::sqrt(static_cast<double>(q.size())) * solver.options().newton.residual_tolerance;
  const double first_order = smallest > 0.0 ? r / smallest : INFINITY;
  return 10.0 * std::min(first_order, std::sqrt(2.0 * solver.size() * r)) + 1e-12 * solver.size();
}

// Every pose converged on the smooth branch, within its allowed distance; every crossing inside the
// sweep reported once, at its angle; the verdicts all true.
void check_smooth_sweep(const CrossingModel& m, const LinkageModel& model, const LinkageSolver& solver, double start,
                        double stop, double step) {
  const LinkageSweep sweep = linkage_sweep(solver, start, stop, step);
  INFO(fmt::format("{} --solver {} --linear {} --sweep {}:{}:{}", m.name, solver.options().solver,
                   solver.options().linear, start, stop, step));
  CHECK(sweep.status == Status::converged);
  CHECK(sweep.branch_kept);
  CHECK(sweep.closed_form_verified);
  CHECK(sweep.flips.empty());
  CHECK(sweep.jumps.empty());
  CHECK(sweep.limits.empty());
  double worst = 0.0;
  for (const LinkagePose& pose : sweep.poses) {
    REQUIRE(pose.outcome.status == Status::converged);
    const double t = pose.driver * deg;
    const double distance = std::max((joint_at(model, pose.q, "A") - m.a(t)).norm(), (joint_at(model, pose.q, "B") - m.b(t)).norm());
    const double allowed = allowed_distance(solver, t, pose.q);
    if (distance > allowed) FAIL_CHECK(fmt::format("pose {}: {:.3g} from the smooth branch (allowed {:.3g})", pose.driver, distance, allowed));
    worst = std::max(worst, distance);
  }
  const int inside = crossings_inside(m, start, stop);
  const int at_start = degrees_from_crossing(m, start) < 1e-9 ? 1 : 0;  // reported when the walk came from the other side
  CHECK(static_cast<int>(sweep.crossings.size()) >= inside);
  CHECK(static_cast<int>(sweep.crossings.size()) <= inside + at_start);
  for (const LinkageCrossing& crossing : sweep.crossings) {
    CHECK(degrees_from_crossing(m, crossing.driver) < 1e-3);
    CHECK_FALSE(crossing.switched);
    CHECK_FALSE(crossing.tangency);
    CHECK(crossing.side_before == -crossing.side_after);
  }
  REQUIRE(sweep.change_points.size() == sweep.crossings.size());
  for (const std::string& words : sweep.change_points) CHECK(words.find("two branches cross at crank") != std::string::npos);
}

const std::vector<std::array<double, 3>>& grids() {
  static const std::vector<std::array<double, 3>> g = {
      {-180.0, 180.0, 2.0},   // poses on both crossings of each model
      {45.0, 405.0, 5.0},     // on the crossings, one turn from 45
      {0.0, 360.0, 10.0},     // starts on a crossing, ends on one
      {90.0, 450.0, 10.0},
      {-3.0, 363.0, 3.0},
      {1.0, 359.0, 0.1},      // 3581 poses of 0.1 degree
      {179.5, 180.5, 0.25},   // sub-steps around one crossing
      {-720.0, 720.0, 7.5},   // four turns, eight crossings
      {0.0, 720.0, 45.0},     // coarse: sub-steps of 2 degrees land on every crossing
      {37.0, 397.0, 30.0},    // coarse, straddling
      {90.0, 90.0, 1.0},      // one pose, on the crossing
      {270.0, -90.0, -4.0},   // backwards
  };
  return g;
}

}  // namespace

TEST_CASE("crossing models: full Newton follows the smooth branch through every crossing on every grid") {
  for (const CrossingModel& m : crossing_models()) {
    const LinkageModel model = model_file(m.name);
    const LinkageSolver solver(model, LinkageSolverOptions{});
    for (const auto& [start, stop, step] : grids()) check_smooth_sweep(m, model, solver, start, stop, step);
  }
}

TEST_CASE("crossing models: every solver agrees on the smooth branch") {
  std::vector<LinkageSolverOptions> all;
  for (const char* linear : {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu"}) all.push_back({"full", linear, {}});
  for (const std::string& name : linkage_solver_names()) {
    if (name != "full") all.push_back({name, "gepp", {}});
  }
  for (const CrossingModel& m : crossing_models()) {
    const LinkageModel model = model_file(m.name);
    for (const LinkageSolverOptions& options : all) {
      const LinkageSolver solver(model, options);
      for (const auto& [start, stop, step] : {std::array<double, 3>{-180.0, 180.0, 2.0}, {45.0, 405.0, 5.0}, {0.0, 720.0, 45.0}}) {
        check_smooth_sweep(m, model, solver, start, stop, step);
      }
    }
  }
}

TEST_CASE("crossing models: a crossing is reported in words with the sides, and switch takes the other branch") {
  SECTION("the isosceles slider-crank's smooth branch, then the one with B at the pivot") {
    const CrossingModel& m = crossing_models()[1];
    const LinkageModel model = model_file(m.name);
    const LinkageSolver solver(model, LinkageSolverOptions{});
    const LinkageSweep smooth = linkage_sweep(solver, 60.0, 120.0, 10.0);
    REQUIRE(smooth.crossings.size() == 1);
    CHECK(smooth.change_points[0].find("two branches cross at crank 90.000 deg; followed the smooth branch; block") !=
          std::string::npos);
    CHECK(smooth.change_points[0].find("changes side from ahead to behind") != std::string::npos);

    const LinkageSweep other = linkage_sweep(solver, 60.0, 180.0, 10.0, {}, AtCrossing::switch_branch);
    CHECK(other.status == Status::converged);
    REQUIRE(other.crossings.size() == 1);
    CHECK(other.crossings[0].switched);
    CHECK(other.change_points[0].find("followed the other branch") != std::string::npos);
    for (const LinkagePose& pose : other.poses) {
      const double t = pose.driver * deg;
      INFO(pose.driver);
      CHECK((joint_at(model, pose.q, "A") - m.a(t)).norm() < 1e-8);
      if (pose.driver < 90.0) CHECK((joint_at(model, pose.q, "B") - m.b(t)).norm() < 1e-8);
      if (pose.driver > 90.0) CHECK(joint_at(model, pose.q, "B").norm() < 1e-8);  // B stays at the pivot
    }
  }
  SECTION("the parallelogram turns into the anti-parallelogram") {
    const CrossingModel& m = crossing_models()[0];
    const LinkageModel model = model_file(m.name);
    const LinkageSolver solver(model, LinkageSolverOptions{});
    const LinkageSweep other = linkage_sweep(solver, 60.0, 170.0, 10.0, {}, AtCrossing::switch_branch);
    REQUIRE(other.status == Status::converged);
    const LinkageSweep through_zero = linkage_sweep(solver, 60.0, -60.0, -10.0, {}, AtCrossing::switch_branch);
    REQUIRE(through_zero.status == Status::converged);
    REQUIRE(through_zero.crossings.size() == 1);
    for (const LinkagePose& pose : through_zero.poses) {
      if (pose.driver >= 0.0) continue;
      const double t = pose.driver * deg;
      const Eigen::Vector2d a = m.a(t), q(4.0, 0.0), b = joint_at(model, pose.q, "B");
      // The anti-parallelogram: B is the parallelogram's B mirrored in the line A-Q.
      const Eigen::Vector2d axis = (q - a).normalized(), smooth = m.b(t);
      const Eigen::Vector2d foot = a + (smooth - a).dot(axis) * axis;
      INFO(pose.driver);
      CHECK((b - (2.0 * foot - smooth)).norm() < 1e-8);
      CHECK((b - smooth).norm() > 0.1);
    }
  }
}

TEST_CASE("crossing models: the verdicts do not depend on the units") {
  for (const CrossingModel& m : crossing_models()) {
    for (const double scale : {1e-12, 1e-8, 1e7, 1e8}) {
      // The same file with every coordinate and length scaled.
      LinkageDescription d = read_linkage_description(model_path(m.name));
      for (auto& joint : d.joints) joint.position *= scale;
      for (auto& link : d.links) link.length *= scale;
      for (auto& slider : d.sliders) slider.through *= scale;
      const LinkageModel model(d);
      const LinkageSolver solver(model, LinkageSolverOptions{});
      const LinkageSweep sweep = linkage_sweep(solver, -180.0, 180.0, 5.0);
      INFO(m.name << " scaled by " << scale);
      CHECK(sweep.status == Status::converged);
      CHECK(sweep.branch_kept);
      CHECK(sweep.closed_form_verified);
      CHECK(sweep.limits.empty());
      // -180 is the parallelogram's crossing: the walk from 60 arrives there going up, and the sweep goes on up.
      const int at_start = degrees_from_crossing(m, -180.0) < 1e-9 ? 1 : 0;
      CHECK(static_cast<int>(sweep.crossings.size()) == crossings_inside(m, -180.0, 180.0) + at_start);
      for (const LinkagePose& pose : sweep.poses) {
        const double t = pose.driver * deg;
        CHECK((joint_at(model, pose.q, "B") / scale - m.b(t)).norm() <= allowed_distance(solver, t, pose.q) / scale);
      }
    }
  }
}

namespace {

// An isosceles slider-crank (B = (2 cos t, 0)) carrying a dyad D with |BD| = 2 and |GD| = 1, G = (2, 1):
// at crank 0, B's dead centre (2, 0), |BG| = 1 = |BD| - |GD| and the circles touch. |BG| - 1 grows
// like t^4 / 2 there, so D's two solutions meet and part again on the same side: a tangency, not a
// crossing. D in closed form: the circle intersection on the reference pose's side.
const char* const tangent_dyad = R"(
[linkage]
name = "tangent-dyad"
[ground]
O = [0.0, 0.0]
G = [2.0, 1.0]
[joints]
A = [0.866, 0.5]
B = [1.732, 0.0]
D = [2.593, 1.805]
[[link]]
joints = ["O", "A"]
length = 1.0
[[link]]
joints = ["A", "B"]
length = 1.0
[[slider]]
joint = "B"
through = [0.0, 0.0]
[[link]]
joints = ["B", "D"]
length = 2.0
[[link]]
joints = ["G", "D"]
length = 1.0
[driver]
type = "crank"
pivot = "O"
joint = "A"
angle = 30.0
)";

}  // namespace

TEST_CASE("crossing models: two branches that touch without crossing are a tangency, on any grid") {
  const LinkageModel model(parse_linkage_description(tangent_dyad, "tangent-dyad.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  for (const auto& [start, stop, step] : {std::array<double, 3>{-20.0, 20.0, 2.0}, {-19.0, 21.0, 4.0}, {-20.0, 20.0, 0.5},
                                          {20.0, -20.0, -5.0}, {-30.0, 30.0, 10.0}}) {
    INFO("--sweep " << start << ":" << stop << ":" << step);
    const LinkageSweep sweep = linkage_sweep(solver, start, stop, step);
    CHECK(sweep.status == Status::converged);
    CHECK(sweep.branch_kept);
    CHECK(sweep.closed_form_verified);
    REQUIRE(sweep.crossings.size() == 1);
    const LinkageCrossing& touch = sweep.crossings.front();
    CHECK(touch.tangency);
    CHECK(touch.side_before == touch.side_after);
    // |BG| - 1 ~ t^4 / 2 is zero to the margin's rounding (1e-6 of the size) within about 0.05 rad.
    CHECK(std::abs(touch.driver) < 3.0);
    CHECK(sweep.change_points.front().find("two branches touch at crank") != std::string::npos);
    for (const LinkagePose& pose : sweep.poses) {
      const double t = pose.driver * deg;
      const Eigen::Vector2d b(2.0 * std::cos(t), 0.0), g(2.0, 1.0), d = joint_at(model, pose.q, "D");
      INFO("pose " << pose.driver);
      CHECK((joint_at(model, pose.q, "B") - b).norm() <= allowed_distance(solver, t, pose.q));
      CHECK(std::abs((d - b).norm() - 2.0) < 1e-8);
      CHECK(std::abs((d - g).norm() - 1.0) < 1e-8);
      // The reference's side of the line B-G all along (right of B -> G), but on the tangency itself,
      // where the two solutions are one.
      if (std::abs(pose.driver) >= 1.0) CHECK(d.x() > 2.0);
    }
  }
}
