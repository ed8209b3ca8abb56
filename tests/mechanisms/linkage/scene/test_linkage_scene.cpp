// The SVG scenes of linkages from descriptions, read back from the SVG text: well-formed tags, one
// element per link, body, slider and joint, joints where the solver put them, velocity arrows in
// the velocities' proportions, and an animation over exactly the poses that assembled.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "linkage_fixtures.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "scenes/linkage_scene.hpp"
#include "svg_reading.hpp"
#include "scenes/scene_layout.hpp"

using namespace numlab::mechanisms;
using numlab::Status;
using numlab::cli::linkage_animation_svg;
using numlab::cli::linkage_pose_svg;
namespace fixtures = numlab::mechanisms::testing;

namespace {

constexpr double printed = 0.0005;  // coordinates are printed with three decimals

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Every opening tag closed in order, one <svg> root: the XML structure a browser needs.
bool balanced(const std::string& svg) {
  std::vector<std::string> open;
  std::size_t roots = 0;
  for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
    const std::size_t end = svg.find('>', at);
    if (end == std::string::npos) return false;
    const std::string tag = svg.substr(at + 1, end - at - 1);
    const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" />", 1) - (tag[0] == '/' ? 1 : 0));
    if (tag[0] == '/') {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    } else if (tag.back() != '/') {
      if (open.empty() && ++roots > 1) return false;
      open.push_back(name);
    }
  }
  return open.empty() && roots == 1 && svg.starts_with("<svg");
}

struct Arrow {
  Eigen::Vector2d from, to;
  double length() const { return (to - from).norm(); }
};
std::vector<Arrow> arrows_of(const std::string& svg) {
  std::vector<Arrow> arrows;
  const std::regex line("class=\"velocity\" x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    arrows.push_back({{std::stod(m[1]), std::stod(m[2])}, {std::stod(m[3]), std::stod(m[4])}});
  }
  return arrows;
}

// The first values="a;b;c" list's length.
std::size_t first_values_count(const std::string& svg) {
  const std::size_t at = svg.find("values=\"");
  REQUIRE(at != std::string::npos);
  const std::string list = svg.substr(at + 8, svg.find('"', at + 8) - at - 8);
  return static_cast<std::size_t>(std::count(list.begin(), list.end(), ';')) + 1;
}

std::size_t assembled(const LinkageSweep& sweep) {
  return static_cast<std::size_t>(std::count_if(sweep.poses.begin(), sweep.poses.end(), [](const LinkagePose& p) {
    return p.outcome.status == Status::converged;
  }));
}

// A Grashof crank-rocker (fixtures::four_bar) in units that make it about 80 across.
LinkageDescription crank_rocker(double size = 10.0) { return fixtures::four_bar(size, 3.5 * size, 3.0 * size, 4.0 * size, 30.0); }

// The crank-rocker with its coupler a body A, B, P, R: P a coupler point off the bar, R inside the
// triangle A, B, P (so the outline is the triangle and R is only a joint on it).
LinkageDescription crank_rocker_with_coupler_body() {
  fixtures::DescriptionBuilder m("coupler");
  const int O = m.ground("O", 0, 0), Q = m.ground("Q", 40, 0);
  const int A = m.joint("A", 8.7, 5.0), B = m.joint("B", 49, 27);
  const int P = m.joint("P", 22, 26), R = m.joint("R", 18, 14);
  m.link(O, A, 10.0);
  m.link(Q, B, 30.0);
  m.body("coupler", {A, B, P, R}, {{0, 0}, {35, 0}, {17.5, 12}, {10.5, 4}});
  m.crank(O, A, 30.0);
  return m.d;
}

}  // namespace

TEST_CASE("A four-bar's pose: bars, joints where the solver put them, arrows in the velocities' proportions", "[scene]") {
  const LinkageModel model(crank_rocker());
  const LinkageSolver solver(model, {});
  const auto sweep = linkage_sweep(solver, 0.0, 355.0, 5.0);
  REQUIRE(sweep.status == Status::converged);
  const std::size_t pose = 6;  // 30 degrees
  const std::string svg = linkage_pose_svg(model, sweep, pose, true);
  CHECK(balanced(svg));
  CHECK_FALSE(balanced(svg.substr(0, svg.rfind("</svg>"))));  // the checker sees a missing close
  CHECK(count(svg, "<line class=\"link\"") == model.description().links.size());
  CHECK(count(svg, "<polygon class=\"body\"") == 0);
  for (const auto& joint : model.description().joints) CHECK(count(svg, ">" + joint.name + "</text>") == 1);
  CHECK(count(svg, "<path class=\"path\"") == model.moving().size());

  // B's circle is the solved B, y flipped, to the printed precision (the picture is over 10 units
  // across, so it is drawn at 1:1).
  const Eigen::Vector2d B = model.positions(sweep.poses[pose].q)[static_cast<std::size_t>(model.description().joint_index("B"))];
  const Eigen::Vector2d drawn = circle_of(svg, "B");
  CHECK(std::abs(drawn.x() - B.x()) <= printed + 1e-12);
  CHECK(std::abs(drawn.y() + B.y()) <= printed + 1e-12);

  // One arrow per moving joint, in the order of model.moving(), each along its velocity; lengths in
  // the ratio of the speeds, the longest 15% of the frame's larger side (over all poses' joints).
  const auto arrows = arrows_of(svg);
  REQUIRE(arrows.size() == model.moving().size());
  const Eigen::VectorXd& v = sweep.poses[pose].velocity;
  auto speed = [&](std::size_t k) { return std::hypot(v[static_cast<Eigen::Index>(2 * k)], v[static_cast<Eigen::Index>(2 * k + 1)]); };
  const double error = 2.0 * std::sqrt(2.0) * printed;  // two rounded ends
  for (std::size_t k = 1; k < arrows.size(); ++k) {
    const double ratio = arrows[k].length() / arrows[0].length();
    INFO("arrow " << k);
    CHECK(std::abs(ratio - speed(k) / speed(0)) <= ratio * (error / arrows[k].length() + error / arrows[0].length()));
  }
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300, longest = 0.0;
  for (const auto& p : sweep.poses) {
    for (const auto& joint : model.positions(p.q)) {
      min_x = std::min(min_x, joint.x()), max_x = std::max(max_x, joint.x());
      min_y = std::min(min_y, joint.y()), max_y = std::max(max_y, joint.y());
    }
  }
  for (const auto& arrow : arrows) longest = std::max(longest, arrow.length());
  CHECK(std::abs(longest - 0.15 * std::max(max_x - min_x, max_y - min_y)) <= error);
  const Eigen::Vector2d direction = arrows[0].to - arrows[0].from;  // A's arrow along A's velocity (y flipped)
  CHECK(std::abs(direction.x() * -v[1] - direction.y() * v[0]) <= error * speed(0));
  CHECK(svg.find("arrows: velocity per radian of crank") != std::string::npos);

  const std::string plain = linkage_pose_svg(model, sweep, pose, false);
  CHECK(arrows_of(plain).empty());
  CHECK(plain.find("arrows:") == std::string::npos);
}

TEST_CASE("The same linkage a thousand times smaller is the same picture", "[scene]") {
  const LinkageModel big(crank_rocker(10.0)), small(crank_rocker(0.01));
  const LinkageSolver big_solver(big, {}), small_solver(small, {});
  const auto big_sweep = linkage_sweep(big_solver, 0.0, 355.0, 5.0), small_sweep = linkage_sweep(small_solver, 0.0, 355.0, 5.0);
  const std::string big_svg = linkage_pose_svg(big, big_sweep, 6, true), small_svg = linkage_pose_svg(small, small_sweep, 6, true);
  for (const char* joint : {"O", "A", "B", "Q"}) {
    INFO(joint);
    CHECK((circle_of(small_svg, joint) - circle_of(big_svg, joint)).norm() <= 2.0 * printed);
  }
  const auto big_arrows = arrows_of(big_svg), small_arrows = arrows_of(small_svg);
  REQUIRE(small_arrows.size() == big_arrows.size());
  for (std::size_t k = 0; k < big_arrows.size(); ++k) CHECK(std::abs(small_arrows[k].length() - big_arrows[k].length()) <= 4.0 * printed);
}

TEST_CASE("A body is one polygon, its outline the hull of its joints", "[scene]") {
  const LinkageModel model(crank_rocker_with_coupler_body());
  const LinkageSolver solver(model, {});
  const auto sweep = linkage_sweep(solver, 0.0, 350.0, 10.0);
  REQUIRE(sweep.status == Status::converged);
  const std::string svg = linkage_pose_svg(model, sweep, 3, false);
  CHECK(balanced(svg));
  CHECK(count(svg, "<line class=\"link\"") == 2);
  REQUIRE(count(svg, "<polygon class=\"body\"") == 1);
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("<polygon class=\"body\" points=\"([^\"]*)\"")));
  const std::string points = m[1];
  CHECK(std::count(points.begin(), points.end(), ',') == 3);  // A, B, P; R lies inside
  for (const char* joint : {"A", "B", "P"}) {
    const Eigen::Vector2d c = circle_of(svg, joint);
    CHECK(points.find(fmt::format("{:.3f},{:.3f}", c.x(), c.y())) != std::string::npos);
  }
  CHECK(count(svg, "id=\"joint-R\"") == 1);
  const std::string animation = linkage_animation_svg(model, sweep, 4.0);
  CHECK(balanced(animation));
  CHECK(count(animation, "attributeName=\"points\"") == 1);
}

TEST_CASE("A slider-crank: the slider's dashed line, its block, and both joints' arrows", "[scene]") {
  const LinkageModel model(fixtures::slider_crank(10.0, 30.0, 5.0, 40.0));
  const LinkageSolver solver(model, {"analytic", "gepp", {}});
  const auto sweep = linkage_sweep(solver, 0.0, 355.0, 5.0);
  REQUIRE(sweep.status == Status::converged);
  const std::string svg = linkage_pose_svg(model, sweep, 8, true);
  CHECK(balanced(svg));
  CHECK(count(svg, "<line class=\"link\"") == 2);
  CHECK(count(svg, "<line class=\"guide\"") == 1);
  CHECK(count(svg, "<g class=\"slider\"") == 1);
  const auto arrows = arrows_of(svg);
  REQUIRE(arrows.size() == 2);
  CHECK(std::abs(arrows[1].from.y() - arrows[1].to.y()) <= 2.0 * printed);  // S moves along its line y = e
  // The guide is the line y = e (SVG y = -e).
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("class=\"guide\" x1=\"[-0-9.]+\" y1=\"([-0-9.]+)\" x2=\"[-0-9.]+\" y2=\"([-0-9.]+)\"")));
  CHECK(std::stod(m[1]) == Approx(-5.0).margin(printed));
  CHECK(std::stod(m[2]) == Approx(-5.0).margin(printed));

  const std::string animation = linkage_animation_svg(model, sweep, 3.0);
  CHECK(balanced(animation));
  CHECK(count(animation, "<animateTransform") == 1);
  CHECK(first_values_count(animation) == sweep.poses.size() + 1);  // back to the first pose
}

TEST_CASE("The animation moves every joint through the assembled poses only, and says what it skipped", "[scene]") {
  // Not Grashof: the crank stops near 130 degrees (where |AQ| = b + c); the poses past it do not assemble.
  const LinkageModel model(fixtures::four_bar(20.0, 30.0, 25.0, 40.0, 60.0));
  const LinkageSolver solver(model, {});
  const auto sweep = linkage_sweep(solver, 0.0, 180.0, 5.0);
  const std::size_t good = assembled(sweep);
  REQUIRE(good > 2);
  REQUIRE(good < sweep.poses.size());
  const std::string svg = linkage_animation_svg(model, sweep, 5.0);
  CHECK(balanced(svg));
  CHECK(first_values_count(svg) == good + 1);
  CHECK(count(svg, "attributeName=\"cx\"") == model.description().joints.size());
  CHECK(svg.find(fmt::format("{} of {} poses did not assemble and are skipped", sweep.poses.size() - good,
                             sweep.poses.size())) != std::string::npos);
  // A pose that did not assemble is not drawn.
  CHECK_THROWS_AS(linkage_pose_svg(model, sweep, sweep.poses.size() - 1, false), std::invalid_argument);
  CHECK(balanced(linkage_pose_svg(model, sweep, 0, true)));
}

TEST_CASE("With no assembled pose there is nothing to draw", "[scene]") {
  const LinkageModel model(crank_rocker());
  LinkageSweep empty;
  try {
    (void)linkage_animation_svg(model, empty, 1.0);
    FAIL("drew an empty sweep");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "no assembled pose to draw");
  }
  LinkageSweep failed;
  failed.poses.resize(3);  // poses that never converged (status running)
  CHECK_THROWS_AS(linkage_animation_svg(model, failed, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(linkage_pose_svg(model, failed, 0, false), std::invalid_argument);
}

TEST_CASE("A velocity that is not finite is said so, not drawn", "[scene]") {
  const LinkageModel model(crank_rocker());
  const LinkageSolver solver(model, {});
  auto sweep = linkage_sweep(solver, 0.0, 355.0, 5.0);
  sweep.poses[6].velocity[1] = std::numeric_limits<double>::quiet_NaN();
  const std::string svg = linkage_pose_svg(model, sweep, 6, true);
  CHECK(arrows_of(svg).empty());
  CHECK(svg.find("the velocity at this pose is not finite") != std::string::npos);
  CHECK_FALSE(std::regex_search(svg, std::regex("\\b(nan|inf)\\b")));  // no number printed from it
}

TEST_CASE("Layout: the hull of a body, the clearest side of a joint, a line across a frame", "[scene]") {
  using numlab::cli::Frame;
  // A square with one joint inside and one on an edge: the outline is the four corners.
  const BodySpec body{"square", {10, 11, 12, 13, 14, 15}, {{0, 0}, {0.5, 0.5}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}, {}};
  std::vector<int> outline = numlab::cli::body_outline(body);
  CHECK(outline == std::vector<int>{10, 12, 13, 15});  // counter-clockwise from the lowest-left corner
  // Bars to the right and up: the name goes down-left.
  const Eigen::Vector2d side = numlab::cli::clearest_direction({{1, 0}, {0, 1}});
  CHECK(side.x() == Approx(-std::sqrt(0.5)));
  CHECK(side.y() == Approx(-std::sqrt(0.5)));
  Eigen::Vector2d from, to;
  REQUIRE(numlab::cli::line_across(Frame{0, 10, 0, 5}, {3, 1}, {1, 0}, from, to));
  CHECK(from == Eigen::Vector2d(0, 1));
  CHECK(to == Eigen::Vector2d(10, 1));
  CHECK_FALSE(numlab::cli::line_across(Frame{0, 10, 0, 5}, {3, 7}, {1, 0}, from, to));
  const double r = std::sqrt(0.5);
  REQUIRE(numlab::cli::line_across(Frame{0, 10, 0, 5}, {1, 1}, {r, r}, from, to));
  CHECK((from - Eigen::Vector2d(0, 0)).norm() < 1e-12);
  CHECK((to - Eigen::Vector2d(5, 5)).norm() < 1e-12);
}
