// The derived model of a linkage: mobility, structure, blocks, and every solver against
// independent closed forms (Freudenstein's equation, the offset slider-crank's formulas).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "linkage_fixtures.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"

using namespace numlab::mechanisms;
using numlab::Status;
namespace fixtures = numlab::mechanisms::testing;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

// Freudenstein's equation for the rocker angle p (the angle of Q->B) at crank angle t:
//   K1 cos p - K2 cos t + K3 = cos(t - p),  K1 = d/a, K2 = d/c, K3 = (a^2 - b^2 + c^2 + d^2) / (2 a c),
// solved in closed form: a quadratic in tan(p/2), whose two roots (sign = +-1) are the two branches.
double freudenstein_rocker(double a, double b, double c, double d, double t, int sign) {
  const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2.0 * a * c);
  const double A = std::cos(t) - K1 - K2 * std::cos(t) + K3;
  const double B = -2.0 * std::sin(t);
  const double C = K1 - (K2 + 1.0) * std::cos(t) + K3;
  const double root = std::sqrt(B * B - 4.0 * A * C);
  return 2.0 * std::atan2(-B + sign * root, 2.0 * A);
}

Eigen::Vector2d joint(const LinkageModel& model, const Eigen::VectorXd& q, const char* name) {
  return model.positions(q)[static_cast<std::size_t>(model.description().joint_index(name))];
}

}  // namespace

TEST_CASE("A four-bar has mobility 1 and blocks crank, then one circle-circle dyad", "[linkage]") {
  const LinkageModel model(fixtures::four_bar(1.0, 3.5, 3.0, 4.0, 30.0));
  const Mobility m = gruebler_kutzbach(model.description());
  CHECK(m.members == 4);
  CHECK(m.lower_pairs == 4);
  CHECK(m.mobility == 1);
  CHECK(model.unknown_count() == 4);
  CHECK(model.equation_count() == 4);
  const auto blocks = linkage_blocks(model);
  REQUIRE(blocks.size() == 2);
  CHECK(describe_block(model, blocks[0]) == "A from (O): crank, explicit");
  CHECK(describe_block(model, blocks[1]) == "B from (A, Q): dyad, closed form (circle-circle)");
}

TEST_CASE("A four-bar without its rocker is named: its joint has fewer equations than unknowns", "[linkage]") {
  auto d = fixtures::four_bar(1.0, 3.5, 3.0, 4.0, 30.0);
  d.links.pop_back();  // Q-B
  try {
    const LinkageModel model(d);
    FAIL("a mobility-2 linkage was accepted");
  } catch (const LinkageFileError& e) {
    CHECK(e.problem() == "joint B: 1 equation for 2 unknowns; mobility 2 (Gruebler-Kutzbach 3 (n - 1) - 2 j1 = "
                         "3 (3 - 1) - 2 (2) = 2), one driver needs 1");
    CHECK(e.place().line == 4);  // B's line in the fixture
  }
}

TEST_CASE("A link between two ground joints is over-constrained and named", "[linkage]") {
  auto d = fixtures::four_bar(1.0, 3.5, 3.0, 4.0, 30.0);
  d.links.push_back({0, 1, 4.0, {77, 3}});
  try {
    const LinkageModel model(d);
    FAIL("an over-constrained linkage was accepted");
  } catch (const LinkageFileError& e) {
    CHECK(e.problem().starts_with("link O-Q: 1 equation for 0 unknowns"));
    CHECK(e.place().line == 77);
  }
}

TEST_CASE("The model's Jacobian agrees with finite differences", "[linkage]") {
  const LinkageModel model(fixtures::slider_crank(1.0, 3.0, 0.5, 40.0));
  const LinkageSystem system(model, 40.0 * deg);
  const auto check = numlab::nonlinear::check_jacobian(system, model.unknowns(model.rough_positions()));
  CHECK(check.agrees);
  CHECK(check.worst_error < 1e-7);
}

TEST_CASE("Every solver reproduces Freudenstein's rocker angle over a crank cycle", "[linkage]") {
  const double a = 1.0, b = 3.5, c = 3.0, d = 4.0;  // Grashof crank-rocker: s + l = 5 <= p + q = 6.5
  const LinkageModel model(fixtures::four_bar(a, b, c, d, 30.0));
  for (const std::string solver : {"full", "sequential", "analytic", "gsl-hybridsj", "gsl-newton"}) {
    LinkageSolverOptions options;
    options.solver = solver;
    const LinkageSolver linkage(model, options);
    const auto sweep = linkage_sweep(linkage, 0.0, 359.0, 1.0);
    INFO(solver);
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.branch_kept);
    CHECK(sweep.limits.empty());
    // The reference pose picks one of Freudenstein's two roots; the sweep must stay on it.
    const auto rocker_at = [&](const Eigen::VectorXd& q) {
      const Eigen::Vector2d B = joint(model, q, "B");
      return std::atan2(B.y(), B.x() - d);
    };
    const auto distance = [](double x, double y) { return std::abs(std::remainder(x - y, 2.0 * pi)); };
    const double t_ref = 30.0 * deg;
    const int sign = distance(rocker_at(linkage.reference()), freudenstein_rocker(a, b, c, d, t_ref, 1)) <
                             distance(rocker_at(linkage.reference()), freudenstein_rocker(a, b, c, d, t_ref, -1))
                         ? 1
                         : -1;
    double worst = 0.0;
    for (const auto& pose : sweep.poses) {
      worst = std::max(worst, distance(rocker_at(pose.q), freudenstein_rocker(a, b, c, d, pose.driver * deg, sign)));
    }
    // kappa(J) is at most ~1e2 here; with ||Phi|| <= 1e-9, angles agree to about 1e-8 rad.
    CHECK(worst < 1e-8);
  }
}

TEST_CASE("The offset slider-crank's slider position, velocity and acceleration match the closed form", "[linkage]") {
  const double r = 1.0, l = 3.0, e = 0.5;
  const LinkageModel model(fixtures::slider_crank(r, l, e, 40.0));
  const LinkageSolver linkage(model, {"analytic", "gepp", {}});
  const auto sweep = linkage_sweep(linkage, 0.0, 355.0, 5.0);
  REQUIRE(sweep.status == Status::converged);
  const int column = model.column_of(model.description().joint_index("S"));
  for (const auto& pose : sweep.poses) {
    const double t = pose.driver * deg;
    // x = r cos t + sqrt(l^2 - (r sin t - e)^2), and its first two derivatives in t.
    const double h = r * std::sin(t) - e, root = std::sqrt(l * l - h * h);
    const double x = r * std::cos(t) + root;
    const double dh = r * std::cos(t), ddh = -r * std::sin(t);
    const double dx = -r * std::sin(t) - h * dh / root;
    const double ddx = -r * std::cos(t) - (dh * dh + h * ddh) / root - (h * dh) * (h * dh) / (root * root * root);
    INFO("crank " << pose.driver);
    CHECK(pose.q(column) == Approx(x).margin(1e-12));
    CHECK(pose.q(column + 1) == Approx(e).margin(1e-12));
    CHECK(pose.velocity(column) == Approx(dx).margin(1e-11));
    CHECK(pose.acceleration(column) == Approx(ddx).margin(1e-10));
    CHECK(pose.velocity(column + 1) == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("Velocities and accelerations from the Jacobian agree with finite differences of positions", "[linkage]") {
  const LinkageModel model(fixtures::four_bar(1.0, 3.5, 3.0, 4.0, 30.0));
  const LinkageSolver linkage(model, {});
  const auto sweep = linkage_sweep(linkage, 0.0, 350.0, 10.0);
  REQUIRE(sweep.status == Status::converged);
  for (const auto& pose : sweep.poses) {
    const auto check = check_derivatives(linkage, pose.driver * deg, pose.q);
    REQUIRE(check.solved);
    // Central difference, h = 1e-5: truncation h^2 |q'''| / 6 and rounding eps |q| / h, both < 1e-9.
    CHECK(check.velocity_difference < 1e-8 * std::max(1.0, check.velocity_scale));
    // 7-point stencil, h = 0.01: rounding 1088 dq / (180 h^2) ~ 6e4 dq, with every position solved
    // again to dq ~ kappa(J) 64 eps |q| ~ 1e-12 (kappa <= 4): ~6e-8; truncation h^6 |q^(8)| / 560 ~ 1e-15.
    CHECK(check.acceleration_difference < 1e-7 * std::max(1.0, check.acceleration_scale));
  }
}

TEST_CASE("A non-Grashof four-bar's crank limits are found by bisection to 0.01 degrees", "[linkage]") {
  // s + l = 2 + 4 > p + q = 3 + 2.5: not Grashof, the crank cannot turn; it stops where A, B, Q
  // line up with |AQ| = b + c.
  const double a = 2.0, b = 3.0, c = 2.5, d = 4.0;
  const LinkageModel model(fixtures::four_bar(a, b, c, d, 60.0));
  for (const std::string solver : {"full", "analytic"}) {
    const LinkageSolver linkage(model, {solver, "gepp", {}});
    const auto sweep = linkage_sweep(linkage, 0.0, 180.0, 1.0);
    INFO(solver);
    CHECK(sweep.status != Status::converged);
    REQUIRE(!sweep.limits.empty());
    // |AQ|^2 = a^2 + d^2 - 2 a d cos t: the limit where |AQ| = b + c.
    const double limit = std::acos((a * a + d * d - (b + c) * (b + c)) / (2.0 * a * d)) / deg;
    CHECK(std::abs(sweep.limits[0].driver - limit) <= 0.01);
    CHECK(sweep.limits[0].bracket <= 0.01);
    REQUIRE(sweep.limits[0].block == 1);  // B's dyad
    // At the limit the coupler and rocker are straight: transmission angle 180 degrees.
    CHECK(sweep.limits[0].transmission_deg > 170.0);
  }
}

TEST_CASE("analytic is refused when a block needs Newton; an unknown solver is refused", "[linkage]") {
  const LinkageModel model(fixtures::four_bar(1.0, 3.5, 3.0, 4.0, 30.0));
  CHECK_THROWS_AS(LinkageSolver(model, {"bogus", "gepp", {}}), std::invalid_argument);
  CHECK_THROWS_AS(LinkageSolver(model, {"full", "bogus", {}}), std::invalid_argument);
}

TEST_CASE("A reference pose that does not assemble is bad input", "[linkage]") {
  // A coupler too short to reach the rocker at any crank angle.
  auto d = fixtures::four_bar(1.0, 0.5, 1.0, 4.0, 30.0);
  const LinkageModel model(d);
  try {
    const LinkageSolver linkage(model, {});
    FAIL("accepted");
  } catch (const LinkageFileError& e) {
    CHECK(std::string(e.problem()).starts_with("the reference pose does not assemble"));
  }
}
