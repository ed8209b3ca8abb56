// Every link's angle, angular velocity and angular acceleration (link_motion.hpp) against the
// textbook's closed forms (Freudenstein's positions and the vector loop's derivatives for a
// four-bar; the offset slider-crank's rod) and against central differences of solved poses, at
// several crank angles, in the file's units and scaled to mm and km.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>

#include "closed_forms.hpp"
#include "four_bar_text.hpp"
#include "model_files.hpp"
#include "newton_polish.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

// Solved pose, velocity and acceleration at crank angle `deg`, reached along the reference branch.
struct Solved {
  Eigen::VectorXd q, v, a;
};
Solved solve_at(const LinkageSolver& solver, double deg) {
  const LinkageSweep sweep = linkage_sweep(solver, deg, deg, 1.0);
  REQUIRE(sweep.poses.size() == 1);
  REQUIRE(sweep.poses[0].outcome.status == numlab::Status::converged);
  return {sweep.poses[0].q, sweep.poses[0].velocity, sweep.poses[0].acceleration};
}

AngularMotion motion_of(const LinkageModel& model, const Solved& s, const std::string& link) {
  const auto lines = link_lines(model.description());
  const auto joints = joint_motions(model, s.q, s.v, s.a);
  for (const LinkLine& line : lines) {
    if (line.name == link) return angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]);
  }
  FAIL("no link " << link);
  return {};
}

// slider-crank.toml with every length times `scale`.
std::string slider_crank_text(double scale) {
  return fmt::format("[linkage]\nname = \"sc\"\n[ground]\nO = [0.0, 0.0]\n[joints]\nA = [{0:.17g}, {1:.17g}]\nS = [{2:.17g}, {3:.17g}]\n"
                     "[[link]]\njoints = [\"O\", \"A\"]\nlength = {4:.17g}\n[[link]]\njoints = [\"A\", \"S\"]\nlength = {5:.17g}\n"
                     "[[slider]]\njoint = \"S\"\nthrough = [0.0, {3:.17g}]\n[driver]\ntype = \"crank\"\npivot = \"O\"\n"
                     "joint = \"A\"\nangle = 30.0\n",
                     0.87 * scale, 0.5 * scale, 4.0 * scale, 0.4 * scale, 1.0 * scale, 3.2 * scale);
}

double angle_gap(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * pi)); }

// The vector loop a e^{i t2} + b e^{i t3} - c e^{i t4} - d = 0 differentiated once and twice with
// omega2 = 1, alpha2 = 0, solved for (omega3, omega4) and (alpha3, alpha4) by Cramer's rule.
struct LoopRates {
  double w3, w4, a3, a4;
};
LoopRates vector_loop(double a, double b, double c, double t2, double t3, double t4) {
  // b w3 (-sin t3, cos t3) - c w4 (-sin t4, cos t4) = -a (-sin t2, cos t2)
  const double m11 = -b * std::sin(t3), m12 = c * std::sin(t4), m21 = b * std::cos(t3), m22 = -c * std::cos(t4);
  const double det = m11 * m22 - m12 * m21;
  const auto solve = [&](double r1, double r2) { return std::pair{(r1 * m22 - m12 * r2) / det, (m11 * r2 - m21 * r1) / det}; };
  const auto [w3, w4] = solve(a * std::sin(t2), -a * std::cos(t2));
  // b a3 i e^{i t3} - c a4 i e^{i t4} = a e^{i t2} + b w3^2 e^{i t3} - c w4^2 e^{i t4}
  const auto [a3, a4] = solve(a * std::cos(t2) + b * w3 * w3 * std::cos(t3) - c * w4 * w4 * std::cos(t4),
                              a * std::sin(t2) + b * w3 * w3 * std::sin(t3) - c * w4 * w4 * std::sin(t4));
  return {w3, w4, a3, a4};
}

// Freudenstein's coupler angle (Norton's K4, K5 form) for the branch `sign`.
double freudenstein_coupler(double a, double b, double c, double d, double t, int sign) {
  const double K1 = d / a, K4 = d / b, K5 = (c * c - d * d - a * a - b * b) / (2.0 * a * b);
  const double D = std::cos(t) - K1 + K4 * std::cos(t) + K5, E = -2.0 * std::sin(t);
  const double F = K1 + (K4 - 1.0) * std::cos(t) + K5;
  return 2.0 * std::atan2(-E + sign * std::sqrt(E * E - 4.0 * D * F), 2.0 * D);
}

void check_four_bar(const std::string& text, double a, double b, double c, double d) {
  const LinkageModel model(parse_linkage_description(text, "fb.toml"));
  LinkageSolverOptions options;
  options.newton.residual_tolerance = 1e-13;
  const LinkageSolver solver(model, options);
  double worst_angle = 0, worst_omega = 0, worst_alpha = 0, worst_fd_omega = 0, worst_fd_alpha = 0;
  for (double deg : {0.0, 35.0, 100.0, 170.0, 230.0, 300.0}) {
    const double t = deg * pi / 180.0;
    const Solved s = solve_at(solver, deg);
    const AngularMotion crank = motion_of(model, s, "crank"), coupler = motion_of(model, s, "coupler"),
                        rocker = motion_of(model, s, "rocker");
    CHECK(angle_gap(crank.angle, t) < 1e-12);
    CHECK(std::abs(crank.omega - 1.0) < 1e-12);
    CHECK(std::abs(crank.alpha) < 1e-11);
    // Freudenstein: of the two branches, the one the model follows; the other is far.
    double t3 = 0, t4 = 0, gap = 1e300;
    for (int sign : {1, -1}) {
      const double p3 = freudenstein_coupler(a, b, c, d, t, sign), p4 = freudenstein_rocker(a, b, c, d, t, sign);
      const double g = angle_gap(p3, coupler.angle) + angle_gap(p4, rocker.angle);
      if (g < gap) gap = g, t3 = p3, t4 = p4;
    }
    worst_angle = std::max({worst_angle, angle_gap(t3, coupler.angle), angle_gap(t4, rocker.angle)});
    const LoopRates loop = vector_loop(a, b, c, t, t3, t4);
    worst_omega = std::max({worst_omega, std::abs(coupler.omega - loop.w3) / (1 + std::abs(loop.w3)),
                            std::abs(rocker.omega - loop.w4) / (1 + std::abs(loop.w4))});
    worst_alpha = std::max({worst_alpha, std::abs(coupler.alpha - loop.a3) / (1 + std::abs(loop.a3)),
                            std::abs(rocker.alpha - loop.a4) / (1 + std::abs(loop.a4))});
    // Central differences of poses solved to rounding, h = 1e-4 rad: O(h^2) truncation, and
    // rounding eps / h^2 = 2e-8 in the second difference.
    const double h = 1e-4;
    const auto angle_at = [&](double x, const std::string& link) {
      const Solved p{polish(model, x, s.q), Eigen::VectorXd::Zero(s.q.size()), Eigen::VectorXd::Zero(s.q.size())};
      return motion_of(model, p, link).angle;
    };
    for (const auto& [link, m] : {std::pair{"coupler", coupler}, std::pair{"rocker", rocker}}) {
      const double up = angle_at(t + h, link), mid = angle_at(t, link), down = angle_at(t - h, link);
      const double d1 = std::remainder(up - down, 2 * pi) / (2 * h);
      const double d2 = (std::remainder(up - mid, 2 * pi) - std::remainder(mid - down, 2 * pi)) / (h * h);
      worst_fd_omega = std::max(worst_fd_omega, std::abs(m.omega - d1) / (1 + std::abs(d1)));
      worst_fd_alpha = std::max(worst_fd_alpha, std::abs(m.alpha - d2) / (1 + std::abs(d2)));
    }
  }
  INFO("angle " << worst_angle << " rad, omega " << worst_omega << ", alpha " << worst_alpha << " (relative to the closed form); "
                << "against differences: omega " << worst_fd_omega << ", alpha " << worst_fd_alpha);
  CHECK(worst_angle < 1e-10);
  CHECK(worst_omega < 1e-9);
  CHECK(worst_alpha < 1e-8);
  CHECK(worst_fd_omega < 1e-7);
  CHECK(worst_fd_alpha < 1e-5);
}

}  // namespace

TEST_CASE("Link angles, omega and alpha of a four-bar match Freudenstein and the vector loop", "[link-motion]") {
  // The shipped four-bar's proportions (1.5, 4, 3.5, 4.5), and Norton's 40, 120, 80, 100 in mm and in km.
  SECTION("four-bar.toml's lengths") { check_four_bar(four_bar_text(1.5, 4, 3.5, 4.5, 1.0), 1.5, 4, 3.5, 4.5); }
  SECTION("40, 120, 80, 100 mm") { check_four_bar(four_bar_text(40, 120, 80, 100, 1.0), 40, 120, 80, 100); }
  SECTION("the same in km") { check_four_bar(four_bar_text(40, 120, 80, 100, 1e-6), 40e-6, 120e-6, 80e-6, 100e-6); }
  SECTION("the crossed branch") { check_four_bar(four_bar_text(40, 120, 80, 100, 1.0, 60.0, -1), 40, 120, 80, 100); }
}

TEST_CASE("The slider-crank's rod angle, omega and alpha match the closed form", "[link-motion]") {
  // slider-crank.toml: r = 1, l = 3.2, the slider on y = e = 0.4. The rod A-S: sin phi = (e - r sin t) / l,
  // phi' = -r cos t / (l cos phi), phi'' = (r sin t + l sin phi phi'^2) / (l cos phi).
  for (double scale : {1.0, 1e3, 1e-6}) {
    const LinkageModel model = scale == 1.0 ? model_file("slider-crank")
                                            : LinkageModel(parse_linkage_description(slider_crank_text(scale), "sc.toml"));
    const LinkageSolver solver(model, {});
    const double r = 1.0, l = 3.2, e = 0.4;
    for (double deg : {0.0, 45.0, 120.0, 200.0, 275.0, 330.0}) {
      const double t = deg * pi / 180.0;
      const Solved s = solve_at(solver, deg);
      const AngularMotion rod = motion_of(model, s, "A-S");
      const double phi = std::asin((e - r * std::sin(t)) / l);
      const double w = -r * std::cos(t) / (l * std::cos(phi));
      const double al = (r * std::sin(t) + l * std::sin(phi) * w * w) / (l * std::cos(phi));
      INFO("scale " << scale << ", crank " << deg);
      CHECK(angle_gap(rod.angle, phi) < 1e-10);
      CHECK(std::abs(rod.omega - w) < 1e-9 * (1 + std::abs(w)));
      CHECK(std::abs(rod.alpha - al) < 1e-8 * (1 + std::abs(al)));
    }
  }
}

TEST_CASE("A link's angle follows its joints' order and its name; the mechanical advantage is honest at a toggle",
          "[link-motion]") {
  const JointMotion O{{0, 0}, {0, 0}, {0, 0}}, A{{0, 2}, {-2, 0}, {0, -2}};  // A on a circle of 2, omega 1
  const AngularMotion m = angular_motion(O, A);
  CHECK(m.angle == Approx(pi / 2));
  CHECK(m.omega == Approx(1.0));
  CHECK(std::abs(m.alpha) < 1e-15);
  CHECK(angular_motion(A, O).angle == Approx(-pi / 2));
  CHECK(std::isinf(mechanical_advantage(0.0)));
  CHECK(std::isinf(mechanical_advantage(-0.0)));
  CHECK(mechanical_advantage(-0.0) > 0);
  CHECK(std::isnan(mechanical_advantage(std::nan(""))));
  CHECK(mechanical_advantage(-0.25) == -4.0);
}
