// Two inputs (issue 30 §1): the shipped five-bar (mechanisms/models/five-bar.toml, two cranks of 2 on
// pivots 4 apart, links of 4 meeting at P) against its closed form, written here from the geometry:
// A and D on their cranks' circles, P the upper intersection of the circles of radius 4 about them.
//  - a sweep of the first crank with the second held: P, velocity and acceleration, the links'
//    angles and their rates (central differences of the closed form in the first angle);
//  - a --drivers path moving both: P at every row, and the path's second-driver values;
//  - statics with a force at P: both driver torques by virtual work (tau_k = -F . dP/dt_k, the
//    closed form's partials by central differences), in units, mm and km;
//  - mobility: two drivers on a four-bar, one on the five-bar, a third [[driver]], a held motor:
//    each refused with its place and the count.

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "model_files.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/mechanisms/linkage/driver_path.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

// P of a five-bar of the shipped shape scaled by `s`, cranks at t1, t2 (radians): the upper
// intersection (left of A -> D) of the circles of radius 4 s about A and D.
Eigen::Vector2d five_bar_pen(double t1, double t2, double s = 1.0) {
  const Eigen::Vector2d A = 2.0 * s * Eigen::Vector2d(std::cos(t1), std::sin(t1));
  const Eigen::Vector2d D = Eigen::Vector2d(4.0 * s, 0.0) + 2.0 * s * Eigen::Vector2d(std::cos(t2), std::sin(t2));
  const Eigen::Vector2d half = (D - A) / 2.0;
  const double height = std::sqrt(16.0 * s * s - half.squaredNorm());
  return A + half + height * Eigen::Vector2d(-half.y(), half.x()) / half.norm();
}

std::string scaled_five_bar(double s) {
  const auto n = [&](double v) { return std::to_string(v * s); };
  return "[linkage]\nname = \"five-bar\"\n[ground]\nO1 = [0, 0]\nO2 = [" + n(4) + ", 0]\n[joints]\nA = [0, " + n(2) +
         "]\nD = [" + n(4) + ", " + n(2) + "]\nP = [" + n(2) + ", " + n(5.5) + "]\n[[link]]\njoints = [\"O1\", \"A\"]\nlength = " +
         n(2) + "\n[[link]]\njoints = [\"O2\", \"D\"]\nlength = " + n(2) + "\n[[link]]\njoints = [\"A\", \"P\"]\nlength = " + n(4) +
         "\n[[link]]\njoints = [\"D\", \"P\"]\nlength = " + n(4) +
         "\n[[driver]]\ntype = \"crank\"\npivot = \"O1\"\njoint = \"A\"\nangle = 90\n"
         "[[driver]]\ntype = \"crank\"\npivot = \"O2\"\njoint = \"D\"\nangle = 90\n"
         "[[load]]\njoint = \"P\"\nforce = [3.0, -10.0]\n";
}

}  // namespace

TEST_CASE("five-bar: a sweep of the first crank with the second held, against the closed form", "[two-drivers]") {
  const LinkageModel model = model_file("five-bar");
  REQUIRE(model.has_second_driver());
  CHECK(model.second_driver() == Approx(90.0).epsilon(1e-15));
  const LinkageSolver solver(model, {});
  const LinkageSweep sweep = linkage_sweep(solver, 40.0, 140.0, 5.0);
  REQUIRE(sweep.status == numlab::Status::converged);
  REQUIRE(sweep.poses.size() == 21);
  const double t2 = 90.0 * deg, h = 1e-4;
  for (const LinkagePose& pose : sweep.poses) {
    const double t1 = pose.driver * deg;
    const Eigen::Vector2d P = joint_at(model, pose.q, "P");
    CHECK((P - five_bar_pen(t1, t2)).norm() <= 1e-9 * 4.0);
    const int column = model.column_of(model.description().joint_index("P"));
    const Eigen::Vector2d v = pose.velocity.segment<2>(column), a = pose.acceleration.segment<2>(column);
    const Eigen::Vector2d v_fd = (five_bar_pen(t1 + h, t2) - five_bar_pen(t1 - h, t2)) / (2 * h);
    const Eigen::Vector2d a_fd = (five_bar_pen(t1 + h, t2) - 2 * five_bar_pen(t1, t2) + five_bar_pen(t1 - h, t2)) / (h * h);
    CHECK((v - v_fd).norm() <= 1e-7 * (1.0 + v.norm()));   // O(h^2) = 1e-8 of the curvature scale
    CHECK((a - a_fd).norm() <= 1e-5 * (1.0 + a.norm()));   // O(eps 4 / h^2) ~ 1e-7 rounding
    CHECK(std::isnan(pose.second_driver));  // a sweep holds the model's value
    // The links' angles (the CSV's angle_/omega_/alpha_ columns): A-P and D-P against the closed
    // form's directions and their central differences in t1 (crank1 turns at 1, crank2 not at all).
    const auto motions = joint_motions(model, pose.q, pose.velocity, pose.acceleration);
    const auto index = [&](const char* name) { return static_cast<std::size_t>(model.description().joint_index(name)); };
    const auto direction = [&](double t, int end) {
      const Eigen::Vector2d from = end == 0 ? Eigen::Vector2d(2.0 * std::cos(t), 2.0 * std::sin(t))
                                            : Eigen::Vector2d(4.0 + 2.0 * std::cos(t2), 2.0 * std::sin(t2));
      const Eigen::Vector2d d = five_bar_pen(t, t2) - from;
      return std::atan2(d.y(), d.x());
    };
    for (const int end : {0, 1}) {
      const AngularMotion link = angular_motion(motions[index(end == 0 ? "A" : "D")], motions[index("P")]);
      const double omega = std::remainder(direction(t1 + h, end) - direction(t1 - h, end), 2 * pi) / (2 * h);
      const double alpha = std::remainder(direction(t1 + h, end) - 2 * direction(t1, end) + direction(t1 - h, end), 2 * pi) / (h * h);
      CHECK(std::abs(std::remainder(link.angle - direction(t1, end), 2 * pi)) <= 1e-9);
      CHECK(std::abs(link.omega - omega) <= 1e-7 * (1.0 + std::abs(omega)));
      CHECK(std::abs(link.alpha - alpha) <= 1e-5 * (1.0 + std::abs(alpha)));
    }
    const AngularMotion crank2 = angular_motion(motions[index("O2")], motions[index("D")]);
    CHECK(crank2.angle == Approx(t2).margin(1e-12));
    CHECK(crank2.omega == Approx(0.0).margin(1e-12));  // held
  }
}

TEST_CASE("five-bar: a --drivers path moves both cranks; each row against the closed form", "[two-drivers]") {
  LinkageModel model = model_file("five-bar");
  const LinkageSolver solver(model, {});
  const auto path = parse_driver_path("crank_deg,crank2_deg\n# a loop about the reference\n90,90\n60,80\n30,110\n"
                                      "70,150\n120,120\n150,60\n90,90\n",
                                      "loop.csv");
  REQUIRE(path.size() == 7);
  const LinkageSweep sweep = solve_driver_path(model, solver, path);
  REQUIRE(sweep.poses.size() == path.size());
  CHECK(sweep.status == numlab::Status::converged);
  CHECK(sweep.branch_kept);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const LinkagePose& pose = sweep.poses[k];
    CHECK(pose.driver == path[k].first);
    CHECK(pose.second_driver == path[k].second);
    const Eigen::Vector2d P = joint_at(model, pose.q, "P");
    CHECK((P - five_bar_pen(path[k].first * deg, path[k].second * deg)).norm() <= 1e-9 * 4.0);
  }
  // Back at the start: the same pose as the reference (the loop did not change branch).
  CHECK((sweep.poses.back().q - solver.reference()).norm() <= 1e-9 * 4.0);
  CHECK(model.second_driver() == Approx(90.0));  // left at the path's last row
}

TEST_CASE("five-bar: a path row past a singular pose is reported singular, and the next row is solved again", "[two-drivers]") {
  LinkageModel model = model_file("five-bar");
  const LinkageSolver solver(model, {});
  // At t1 = 0, t2 = 180 the cranks point at each other and A meets D: the circles about A and D
  // are one, P could be anywhere on it (a singular pose). The path's straight sub-steps from
  // (90, 90) to (-10, 190) pass through it, so the row is not reached, though P exists there
  // (|AD| = 0.06): which side of A-D it lies on is lost at the singular pose.
  const auto path = parse_driver_path("a,b\n90,90\n-10,190\n100,80\n", "apart.csv");
  const LinkageSweep sweep = solve_driver_path(model, solver, path);
  REQUIRE(sweep.poses.size() == 3);
  CHECK(sweep.poses[1].outcome.status == numlab::Status::singular);
  CHECK(sweep.status != numlab::Status::converged);
  CHECK(sweep.poses[2].outcome.status == numlab::Status::converged);
  CHECK((joint_at(model, sweep.poses[2].q, "P") - five_bar_pen(100 * deg, 80 * deg)).norm() <= 1e-9 * 4.0);
}

TEST_CASE("five-bar: both driver torques by virtual work with a force at P, in units, mm and km", "[two-drivers]") {
  for (const double s : {1.0, 1e-3, 1e3}) {
    LinkageModel model(parse_linkage_description(scaled_five_bar(s), "five-bar.toml"));
    const LinkageSolver solver(model, {});
    const auto path = parse_driver_path("a,b\n90,90\n70,110\n120,60\n", "p.csv");
    const LinkageSweep sweep = solve_driver_path(model, solver, path);
    REQUIRE(sweep.status == numlab::Status::converged);
    LinkageStaticsSolver statics(model);
    const Eigen::Vector2d F(3.0, -10.0);
    const double h = 1e-5;
    for (const LinkagePose& pose : sweep.poses) {
      const double t1 = pose.driver * deg, t2 = pose.second_driver * deg;
      const LinkageStatics& result = statics.solve(pose);
      REQUIRE(result.status == StaticsStatus::equilibrium);
      const Eigen::Vector2d dP1 = (five_bar_pen(t1 + h, t2, s) - five_bar_pen(t1 - h, t2, s)) / (2 * h);
      const Eigen::Vector2d dP2 = (five_bar_pen(t1, t2 + h, s) - five_bar_pen(t1, t2 - h, s)) / (2 * h);
      const double scale = F.norm() * 4.0 * s;  // a torque's size: N times the file's length unit
      CHECK(std::abs(result.driver - (-F.dot(dP1))) <= 1e-7 * scale);
      CHECK(std::abs(result.second_driver - (-F.dot(dP2))) <= 1e-7 * scale);
    }
  }
}

TEST_CASE("two drivers: mobility and the [[driver]] tables checked, with the place", "[two-drivers]") {
  const std::string five_bar = numlab::linalg::read_text_file(model_path("five-bar"));
  // One driver on a mobility-2 linkage.
  std::string one = five_bar.substr(0, five_bar.rfind("[[driver]]"));
  CHECK_THROWS_WITH(LinkageModel(parse_linkage_description(one, "f.toml")),
                    Catch::Contains("mobility 2") && Catch::Contains("one driver needs 1"));
  // A third driver.
  CHECK_THROWS_WITH(parse_linkage_description(five_bar + "\n[[driver]]\ntype = \"crank\"\npivot = \"O1\"\njoint = \"A\"\nangle = 0\n", "f.toml"),
                    Catch::Contains("f.toml:") && Catch::Contains("a third [[driver]]"));
  // Two drivers on a four-bar (mobility 1).
  std::string four_bar = numlab::linalg::read_text_file(model_path("four-bar"));
  const auto table = four_bar.find("[driver]");
  REQUIRE(table != std::string::npos);
  four_bar.replace(table, 8, "[[driver]]");
  four_bar += "\n[[driver]]\ntype = \"crank\"\npivot = \"Q\"\njoint = \"B\"\nangle = 60\n";
  CHECK_THROWS_WITH(LinkageModel(parse_linkage_description(four_bar, "g.toml")),
                    Catch::Contains("two drivers need 2"));
  // A motor held second.
  std::string motor = five_bar.substr(0, five_bar.rfind("[[driver]]")) +
                      "[[driver]]\ntype = \"motor\"\npivot = \"P\"\nfrom = \"A\"\njoint = \"D\"\nangle = 60\n";
  CHECK_THROWS_WITH(parse_linkage_description(motor, "m.toml"), Catch::Contains("m.toml:") && Catch::Contains("is a motor"));
}

TEST_CASE("driver paths: bad rows get FILE:LINE and the problem", "[two-drivers]") {
  CHECK_THROWS_WITH(parse_driver_path("a,b\n1,nan\n", "p.csv"), "p.csv:2: the second driver's value 'nan' is not a finite number");
  CHECK_THROWS_WITH(parse_driver_path("1,2\n", "p.csv"), Catch::StartsWith("p.csv:1: no header"));
  CHECK_THROWS_WITH(parse_driver_path("a,b\n1,2,\n", "p.csv"), Catch::StartsWith("p.csv:2: 3 fields"));
  CHECK_THROWS_WITH(parse_driver_path("a,b\n", "p.csv"), Catch::Contains("no rows"));
  CHECK_THROWS_WITH(parse_driver_path("a,b\n1e999,2\n", "p.csv"), Catch::Contains("is not a finite number"));
  CHECK(parse_driver_path("x,y\r\n+1.5, -2\r\n", "p.csv").front().second == -2.0);
  LinkageModel four_bar = model_file("four-bar");
  const LinkageSolver solver(four_bar, {});
  CHECK_THROWS_AS(solve_driver_path(four_bar, solver, {{1.0, 2.0}}), std::invalid_argument);
}
