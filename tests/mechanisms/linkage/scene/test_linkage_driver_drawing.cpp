// Every driver drawn as a driver (issue 30 section 4 with two inputs), read back from the SVG text:
// the five-bar's second crank like its first, in the pose and in the animation, also when a
// --drivers path turns it; a second driver that is a slider (its block pink) or an actuator (a
// cylinder between its joints); and the caption's held value.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/driver_path.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "scenes/linkage_scene.hpp"
#include "svg_reading.hpp"

using namespace numlab::mechanisms;
using numlab::Status;
using numlab::cli::linkage_animation_svg;
using numlab::cli::linkage_pose_svg;
using Point = Eigen::Vector2d;

namespace {

constexpr double printed = 0.0005;  // coordinates are printed with three decimals
constexpr const char* driver_colour = "#c0392b";

// The five-bar of mechanisms/models/five-bar.toml, read from the file.
LinkageDescription five_bar() { return read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/five-bar.toml"); }

// The opening tags (and, for an element with children, everything up to its closing tag) of the
// elements that carry data-driver="number".
std::vector<std::string> driver_elements(const std::string& svg, int number) {
  std::vector<std::string> found;
  const std::string mark = fmt::format(" data-driver=\"{}\"", number);
  for (std::size_t at = svg.find(mark); at != std::string::npos; at = svg.find(mark, at + mark.size())) {
    const std::size_t start = svg.rfind('<', at), end = svg.find('\n', at);
    found.push_back(svg.substr(start, end - start));
  }
  return found;
}

std::string attribute(const std::string& element, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(element, m, std::regex(" " + name + "=\"([^\"]*)\"")));
  return m[1];
}
double number_of(const std::string& element, const std::string& name) { return std::stod(attribute(element, name)); }

// The values of `element`'s <animate> of `name`, as numbers.
std::vector<double> animated(const std::string& element, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(element, m, std::regex("attributeName=\"" + name + "\" dur=\"[0-9.]+s\" repeatCount=\"indefinite\" values=\"([^\"]*)\"")));
  std::vector<double> list;
  std::istringstream in(m[1].str());
  std::string value;
  while (std::getline(in, value, ';')) list.push_back(std::stod(value));
  return list;
}

// A line's two ends.
struct Ends {
  Point a, b;
};
Ends ends_of(const std::string& line) {
  return {{number_of(line, "x1"), number_of(line, "y1")}, {number_of(line, "x2"), number_of(line, "y2")}};
}
bool joins(const Ends& line, const Point& p, const Point& q) {
  return ((line.a - p).norm() <= 2 * printed && (line.b - q).norm() <= 2 * printed) ||
         ((line.a - q).norm() <= 2 * printed && (line.b - p).norm() <= 2 * printed);
}

// The bars in the driver's colour that carry no data-driver mark: none should.
std::size_t unmarked_red_bars(const std::string& svg) {
  std::size_t n = 0;
  std::istringstream in(svg);
  for (std::string line; std::getline(in, line);) {
    if ((line.starts_with("<line class=\"link\"") || line.starts_with("<line class=\"body\"")) &&
        line.find(fmt::format("stroke=\"{}\"", driver_colour)) != std::string::npos && line.find("data-driver") == std::string::npos) {
      ++n;
    }
  }
  return n;
}

// A crank O-A of 2 (first driver) and a slider driver S on the ground line y = 0 (second): A, P, S with
// links A-P, P-S, mobility 2.
const std::string crank_and_slider = R"(
[linkage]
name = "crank-and-slider"
[ground]
O = [0.0, 0.0]
[joints]
A = [0.0, 2.0]
P = [3.0, 4.0]
S = [5.0, 0.0]
[[link]]
joints = ["O", "A"]
length = 2.0
[[link]]
joints = ["A", "P"]
length = 3.605551275463989
[[link]]
joints = ["P", "S"]
length = 4.47213595499958
[[slider]]
joint = "S"
through = [0.0, 0.0]
angle = 0.0
[[driver]]
type = "crank"
pivot = "O"
joint = "A"
angle = 90.0
[[driver]]
type = "slider"
joint = "S"
travel = 5.0
)";

// A crank O1-A of 2 (first driver), a link A-P, and an actuator O2-P (second driver): mobility 2.
const std::string crank_and_actuator = R"(
[linkage]
name = "crank-and-actuator"
[ground]
O1 = [0.0, 0.0]
O2 = [4.0, 0.0]
[joints]
A = [0.0, 2.0]
P = [2.0, 5.0]
[[link]]
joints = ["O1", "A"]
length = 2.0
[[link]]
joints = ["A", "P"]
length = 3.605551275463989
[[driver]]
type = "crank"
pivot = "O1"
joint = "A"
angle = 90.0
[[driver]]
type = "actuator"
joints = ["O2", "P"]
length = 5.385164807134504
)";

LinkageSweep sweep_of(const LinkageModel& model) {
  const LinkageSolver solver(model, LinkageSolverOptions{});
  LinkageSweep sweep = linkage_sweep(solver, 0.0, 350.0, 10.0);
  REQUIRE(sweep.status == Status::converged);
  return sweep;
}

}  // namespace

TEST_CASE("The five-bar's second crank is drawn as its first is, in the pose and in the animation", "[scene][drivers]") {
  const LinkageModel model(five_bar());
  const LinkageSweep sweep = sweep_of(model);
  const std::size_t pose = 3;  // crank 30 deg
  const std::string svg = linkage_pose_svg(model, sweep, pose, false);
  const auto first = driver_elements(svg, 1), second = driver_elements(svg, 2);
  REQUIRE(first.size() == 1);
  REQUIRE(second.size() == 1);
  for (const std::string& crank : {first[0], second[0]}) {
    CHECK(crank.starts_with("<line class=\"link\""));
    CHECK(attribute(crank, "stroke") == driver_colour);
  }
  CHECK(attribute(second[0], "stroke-width") == attribute(first[0], "stroke-width"));
  CHECK(joins(ends_of(first[0]), circle_of(svg, "O1"), circle_of(svg, "A")));
  CHECK(joins(ends_of(second[0]), circle_of(svg, "O2"), circle_of(svg, "D")));
  CHECK(unmarked_red_bars(svg) == 0);  // the links A-P and D-P stay bars
  // Drawn at 10:1 (the five-bar is about 6 across): D is O2 + 2 (cos 90, sin 90), the held crank.
  CHECK((circle_of(svg, "D") - Point(40.0, -20.0)).norm() <= 2 * printed);
  CHECK(svg.find("Five-bar linkage with two cranks at crank 30 deg, crank 90 deg held") != std::string::npos);
  // No path chosen: every moving joint's is drawn, the longest heavier but for the two crank pins.
  CHECK(svg.find("heavier: P's, the longest but the crank pins'") != std::string::npos);

  const std::string animation = linkage_animation_svg(model, sweep, 4.0);
  const auto moving_first = driver_elements(animation, 1), moving_second = driver_elements(animation, 2);
  REQUIRE(moving_first.size() == 1);
  REQUIRE(moving_second.size() == 1);
  CHECK(attribute(moving_second[0], "stroke") == driver_colour);
  CHECK(attribute(moving_second[0], "stroke-width") == attribute(moving_first[0], "stroke-width"));
  CHECK(unmarked_red_bars(animation) == 0);
  CHECK(animation.find("36 poses from crank 0 deg to 350 deg, crank 90 deg held") != std::string::npos);
}

TEST_CASE("On a --drivers path the second crank turns, drawn as a driver, its end where the path puts it", "[scene][drivers]") {
  LinkageModel model(five_bar());
  const LinkageSolver solver(model, LinkageSolverOptions{});
  std::vector<DriverPathPoint> path;
  for (int k = 0; k < 7; ++k) path.push_back({90.0 + 10.0 * k, 90.0 - 8.0 * k});
  const LinkageSweep sweep = solve_driver_path(model, solver, path);
  REQUIRE(sweep.status == Status::converged);
  const std::string animation = linkage_animation_svg(model, sweep, 4.0);
  CHECK(animation.find("both drivers along a path") != std::string::npos);
  const auto second = driver_elements(animation, 2);
  REQUIRE(second.size() == 1);
  CHECK(attribute(second[0], "stroke") == driver_colour);
  // Its end D (x2, y2: the link is O2 -> D) at 10:1 is O2 + 2 (cos t2, sin t2), y down.
  const std::vector<double> x = animated(second[0], "x2"), y = animated(second[0], "y2");
  REQUIRE(x.size() == path.size() + 1);  // once round and back to the first
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double t2 = path[k % path.size()].second * std::numbers::pi / 180.0;
    CHECK(std::abs(x[k] - 10.0 * (4.0 + 2.0 * std::cos(t2))) <= printed);
    CHECK(std::abs(y[k] + 10.0 * 2.0 * std::sin(t2)) <= printed);
  }
  const std::string pose = linkage_pose_svg(model, sweep, 2, false);
  CHECK(pose.find("at crank 110 deg, crank 74 deg") != std::string::npos);
}

TEST_CASE("A second driver that is a slider: its block in the driver's pink, where S is", "[scene][drivers]") {
  const LinkageModel model(parse_linkage_description(crank_and_slider, "crank-and-slider.toml"));
  const LinkageSweep sweep = sweep_of(model);
  for (const std::string& svg : {linkage_pose_svg(model, sweep, 4, false), linkage_animation_svg(model, sweep, 4.0)}) {
    const auto crank = driver_elements(svg, 1), block = driver_elements(svg, 2);
    REQUIRE(crank.size() == 1);
    REQUIRE(block.size() == 1);
    CHECK(attribute(crank[0], "stroke") == driver_colour);
    CHECK(block[0].starts_with("<g class=\"slider\""));
    CHECK(attribute(block[0], "fill") == "#f1948a");
    CHECK(unmarked_red_bars(svg) == 0);
  }
  const std::string svg = linkage_pose_svg(model, sweep, 4, false);
  std::smatch m;
  const std::string block = driver_elements(svg, 2)[0];
  REQUIRE(std::regex_search(block, m, std::regex("translate\\(([-0-9.]+),([-0-9.]+)\\)")));
  CHECK((Point(std::stod(m[1]), std::stod(m[2])) - circle_of(svg, "S")).norm() <= 2 * printed);
  CHECK((circle_of(svg, "S") - Point(50.0, 0.0)).norm() <= 2 * printed);  // travel 5 held, at 10:1
  CHECK(svg.find("slider travel 5 held") != std::string::npos);
}

TEST_CASE("A second driver that is an actuator: a cylinder from O2 to P, barrel in the driver's colour", "[scene][drivers]") {
  const LinkageModel model(parse_linkage_description(crank_and_actuator, "crank-and-actuator.toml"));
  const LinkageSweep sweep = sweep_of(model);
  const std::string svg = linkage_pose_svg(model, sweep, 9, false);  // crank 90 deg
  const auto cylinder = driver_elements(svg, 2);
  REQUIRE(cylinder.size() == 2);  // the rod, then the barrel
  const Point o2 = circle_of(svg, "O2"), p = circle_of(svg, "P");
  CHECK(joins(ends_of(cylinder[0]), o2, p));
  CHECK(joins(ends_of(cylinder[1]), o2, (o2 + p) / 2.0));
  CHECK(attribute(cylinder[1], "stroke") == driver_colour);
  CHECK((p - o2).norm() == Approx(10.0 * 5.385164807134504).margin(4 * printed));  // held at its length
  CHECK(svg.find("actuator length 5.38516 held") != std::string::npos);
  const std::string animation = linkage_animation_svg(model, sweep, 4.0);
  const auto moving = driver_elements(animation, 2);
  REQUIRE(moving.size() == 2);
  CHECK(moving[0].find("<line class=\"actuator\"") == 0);
  CHECK(animated(moving[1], "x2").size() == sweep.poses.size() + 1);
}
