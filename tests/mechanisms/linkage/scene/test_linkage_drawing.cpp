// The drawing an engineer asks for (issue 30 section 4), read back from the SVG text of every shipped
// model: the pose drawn by default is the sweep's best-conditioned one, --draw-at's pose is the one
// asked for, chosen paths are exactly those joints' paths, pivots at one height share one hatched
// ground, the joints' names overlap neither each other nor a bar, and a body whose points lie on
// one line is drawn as a bar.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "scenes/label_placement.hpp"
#include "scenes/linkage_scene.hpp"
#include "svg_reading.hpp"

using namespace numlab::mechanisms;
using numlab::Status;
using numlab::cli::LabelBox;
using numlab::cli::LinkageSceneOptions;
using Point = Eigen::Vector2d;

namespace {

constexpr double printed = 0.0005;  // coordinates are printed with three decimals

// Every shipped model (mechanisms/models/*.toml), by name.
std::vector<std::string> shipped_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(NUMLAB_MODELS_DIR)) {
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}
const std::vector<std::string> shipped = shipped_names();

// A model, its solver and a sweep of it (the solver keeps a reference to the model).
struct Swept {
  std::unique_ptr<LinkageModel> model;
  std::unique_ptr<LinkageSolver> solver;
  LinkageSweep sweep;
};
// A crank or motor over a turn in 5 degree steps; an actuator or slider driver over +-20% of its
// reference value in 40 steps.
Swept swept(LinkageDescription description) {
  Swept s;
  s.model = std::make_unique<LinkageModel>(std::move(description));
  s.solver = std::make_unique<LinkageSolver>(*s.model, LinkageSolverOptions{});
  const DriverSpec& driver = s.model->description().driver;
  const double reference = driver.reference, spread = 0.2 * std::abs(reference);
  s.sweep = driver.angle() ? linkage_sweep(*s.solver, 0.0, 355.0, 5.0)
                           : linkage_sweep(*s.solver, reference - spread, reference + spread, spread / 20.0);
  return s;
}
Swept shipped_model(const std::string& name) {
  return swept(read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/" + name + ".toml"));
}

bool converged(const LinkagePose& pose) { return pose.outcome.status == Status::converged; }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Each name's box from its <text>, in SVG coordinates: centred (text-anchor middle, dominant-baseline
// central), as wide as its characters at 0.62 em each and as tall as a capital (0.75 em): what a sans
// serif font draws, independent of the placement's own (larger) estimate.
struct Name {
  std::string text;
  LabelBox box;
};
std::vector<Name> names_of(const std::string& svg) {
  std::vector<Name> names;
  const std::regex text("<text class=\"name\" x=\"([-0-9.]+)\" y=\"([-0-9.]+)\" font-size=\"([-0-9.e+]+)\"[^>]*>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const double em = std::stod(m[3]);
    const std::string name = m[4];
    names.push_back({name, {{std::stod(m[1]), std::stod(m[2])}, {0.31 * em * static_cast<double>(name.size()), 0.375 * em}}});
  }
  return names;
}

// The bars: every link's line and every body's outline edge (or a bar body's line), with half their
// stroke width.
struct Bar {
  Point a, b;
  double half_width;
};
std::vector<Bar> bars_of(const std::string& svg) {
  std::vector<Bar> bars;
  const std::regex line("<line class=\"(?:link|body)\" x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\""
                        "[^>]*stroke-width=\"([-0-9.e+]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    bars.push_back({{std::stod(m[1]), std::stod(m[2])}, {std::stod(m[3]), std::stod(m[4])}, std::stod(m[5]) / 2.0});
  }
  const std::regex polygon("<polygon class=\"body\" points=\"([^\"]*)\"[^>]*stroke-width=\"([-0-9.e+]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polygon); it != std::sregex_iterator(); ++it) {
    std::vector<Point> corners;
    const std::string list = (*it)[1];
    const std::regex pair("([-0-9.]+),([-0-9.]+)");
    for (auto p = std::sregex_iterator(list.begin(), list.end(), pair); p != std::sregex_iterator(); ++p) {
      corners.emplace_back(std::stod((*p)[1]), std::stod((*p)[2]));
    }
    for (std::size_t k = 0; k < corners.size(); ++k) {
      bars.push_back({corners[k], corners[(k + 1) % corners.size()], std::stod((*it)[2]) / 2.0});
    }
  }
  return bars;
}

// No two names overlap and no name touches a bar; the first problem in words, or "".
std::string crowded_names(const std::string& svg) {
  const auto names = names_of(svg);
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (std::size_t j = i + 1; j < names.size(); ++j) {
      if (numlab::cli::boxes_overlap(names[i].box, names[j].box)) return names[i].text + " overlaps " + names[j].text;
    }
    for (const Bar& bar : bars_of(svg)) {
      if (numlab::cli::box_segment_distance(names[i].box, bar.a, bar.b) <= bar.half_width) {
        return fmt::format("{} sits on the bar ({:.2f}, {:.2f}) - ({:.2f}, {:.2f})", names[i].text, bar.a.x(), bar.a.y(),
                           bar.b.x(), bar.b.y());
      }
    }
  }
  return "";
}

}  // namespace

TEST_CASE("By default the drawn pose is the sweep's best-conditioned pose, for every shipped model", "[scene][drawing]") {
  REQUIRE(shipped.size() >= 15);
  for (const std::string& name : shipped) {
    INFO(name);
    const Swept s = shipped_model(name);
    const auto best = numlab::cli::best_conditioned_pose(*s.model, s.sweep);
    REQUIRE(best);
    REQUIRE(converged(s.sweep.poses[*best]));
    const double kappa = s.sweep.poses[*best].condition;
    REQUIRE(std::isfinite(kappa));
    // The argmin of kappa(J) over the converged poses, the first of equals.
    for (std::size_t k = 0; k < s.sweep.poses.size(); ++k) {
      const LinkagePose& pose = s.sweep.poses[k];
      if (!converged(pose)) continue;
      CHECK(kappa <= pose.condition);
      if (k < *best) CHECK(kappa < pose.condition);
    }
    LinkageSceneOptions options;
    options.pose_reason = "the sweep's best-conditioned pose";
    const std::string svg = numlab::cli::linkage_pose_svg(*s.model, s.sweep, *best, options);
    // A second driver (the five-bar's crank2) is said held at its value before the reason.
    const auto& second = s.model->description().second_driver;
    const std::string held = second ? fmt::format(", {} {:g}{} held", second->kind == DriverKind::crank ? "crank" : "second driver",
                                                  s.model->second_driver(), second->angle() ? " deg" : "")
                                    : "";
    CHECK(svg.find(fmt::format(" {:g}{}{} (the sweep's best-conditioned pose)", s.sweep.poses[*best].driver,
                               s.model->description().driver.angle() ? " deg" : "", held)) != std::string::npos);
  }
  // The Mustang's sweep from its reference pose meets both assembly limits (-41.4 and 56.5 deg),
  // where J is near singular: the pose drawn is far from both, its kappa well below theirs.
  const Swept mustang = shipped_model("mustang");
  const auto best = numlab::cli::best_conditioned_pose(*mustang.model, mustang.sweep);
  double worst = 0.0;
  for (const auto& pose : mustang.sweep.poses) {
    if (converged(pose)) worst = std::max(worst, pose.condition);
  }
  CHECK(mustang.sweep.poses[*best].condition < worst / 2.0);
  // Nothing converged: no pose.
  LinkageSweep failed;
  failed.poses.resize(2);
  CHECK_FALSE(numlab::cli::best_conditioned_pose(*mustang.model, failed));
}

TEST_CASE("pose_at finds a sweep's pose by its driver value, and only a pose of the sweep", "[scene][drawing]") {
  const Swept s = shipped_model("four-bar");
  CHECK(numlab::cli::pose_at(s.sweep, 30.0) == std::optional<std::size_t>(6));
  CHECK(numlab::cli::pose_at(s.sweep, 30.0 + 1e-12) == std::optional<std::size_t>(6));
  CHECK(numlab::cli::pose_at(s.sweep, 0.0) == std::optional<std::size_t>(0));
  CHECK(numlab::cli::pose_at(s.sweep, 355.0) == std::optional<std::size_t>(71));
  CHECK_FALSE(numlab::cli::pose_at(s.sweep, 33.0));
  CHECK_FALSE(numlab::cli::pose_at(s.sweep, 360.0));  // the same pose as 0, but not a value of the sweep
  CHECK_FALSE(numlab::cli::pose_at(s.sweep, 30.001));
}

TEST_CASE("A chosen path is exactly that joint's path over the assembled poses", "[scene][drawing]") {
  for (const std::string& name : {std::string("four-bar"), std::string("jansen"), std::string("mustang")}) {
    INFO(name);
    const Swept s = shipped_model(name);
    const auto& d = s.model->description();
    const int joint = s.model->moving().back();  // the foot F, the roof tip P12, B
    LinkageSceneOptions options;
    options.paths = {joint};
    options.paths_from = "--path";
    const std::size_t pose = *numlab::cli::best_conditioned_pose(*s.model, s.sweep);
    const std::string svg = numlab::cli::linkage_pose_svg(*s.model, s.sweep, pose, options);
    const std::string joint_name = d.joints[static_cast<std::size_t>(joint)].name;
    REQUIRE(count(svg, "<path class=\"path\"") == 1);
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, std::regex("<path class=\"path\" id=\"path-([A-Za-z0-9_]+)\" d=\"([^\"]*)\"")));
    CHECK(m[1] == joint_name);
    // Its vertices are the joint's solved positions, pose by pose (y flipped), a new run after a
    // pose that did not assemble.
    const std::string d_attribute = m[2];
    const std::regex vertex("([ML]) ([-0-9.]+) ([-0-9.]+)");
    std::vector<Point> drawn;
    for (auto it = std::sregex_iterator(d_attribute.begin(), d_attribute.end(), vertex); it != std::sregex_iterator(); ++it) {
      drawn.emplace_back(std::stod((*it)[2]), -std::stod((*it)[3]));
    }
    std::vector<Point> solved;
    for (const auto& p : s.sweep.poses) {
      if (converged(p)) solved.push_back(s.model->positions(p.q)[static_cast<std::size_t>(joint)]);
    }
    REQUIRE(drawn.size() == solved.size());
    // Drawn at a power-of-ten zoom that makes the picture at least 10 units across.
    const double zoom = (circle_of(svg, joint_name).x()) /
                        s.model->positions(s.sweep.poses[pose].q)[static_cast<std::size_t>(joint)].x();
    const double power = std::pow(10.0, std::round(std::log10(zoom)));
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      INFO("vertex " << k);
      CHECK((drawn[k] - solved[k] * power).norm() <= 2.0 * printed);
    }
    CHECK(svg.find(fmt::format("the path of {} over {} assembled poses (--path)", joint_name, solved.size())) != std::string::npos);
  }
}

TEST_CASE("The joints' names overlap neither each other nor a bar, on every shipped model", "[scene][drawing]") {
  for (const std::string& name : shipped) {
    const Swept s = shipped_model(name);
    std::vector<std::size_t> poses = {*numlab::cli::best_conditioned_pose(*s.model, s.sweep)};
    for (std::size_t k = 0; k < s.sweep.poses.size(); k += 9) {  // and every 45 degrees
      if (converged(s.sweep.poses[k])) poses.push_back(k);
    }
    for (const std::size_t pose : poses) {
      INFO(name << " at " << s.sweep.poses[pose].driver << " deg");
      for (const bool arrows : {false, true}) {
        LinkageSceneOptions options;
        options.velocity_arrows = arrows;
        const std::string svg = numlab::cli::linkage_pose_svg(*s.model, s.sweep, pose, options);
        REQUIRE(names_of(svg).size() == s.model->description().joints.size());
        REQUIRE(bars_of(svg).size() >= s.model->description().links.size());
        CHECK(crowded_names(svg) == "");
      }
    }
  }
  // The checker sees two names on top of each other, and a name on a bar.
  const std::string two = "<text class=\"name\" x=\"0\" y=\"0\" font-size=\"4\">AB</text>"
                          "<text class=\"name\" x=\"1\" y=\"1\" font-size=\"4\">C</text>";
  CHECK(crowded_names(two) == "AB overlaps C");
  const std::string on_bar = "<line class=\"link\" x1=\"-5\" y1=\"0\" x2=\"5\" y2=\"0\" stroke=\"#000\" stroke-width=\"1\"/>"
                             "<text class=\"name\" x=\"0\" y=\"1.8\" font-size=\"4\">A</text>";
  CHECK(crowded_names(on_bar).starts_with("A sits on the bar"));
}

TEST_CASE("Ground pivots at one height stand on one hatched strip, others on their own", "[scene][drawing]") {
  const std::regex strip("<path class=\"ground\" d=\"M ([-0-9.]+) ([-0-9.]+) H ([-0-9.]+)");
  auto strips = [&](const std::string& svg) {
    std::vector<std::array<double, 3>> found;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), strip); it != std::sregex_iterator(); ++it) {
      found.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
    }
    return found;
  };
  // The four-bar's O (0, 0) and Q (4.5, 0): one strip under both, reaching past each.
  const Swept four = shipped_model("four-bar");
  const std::string svg = numlab::cli::linkage_pose_svg(*four.model, four.sweep, 0, LinkageSceneOptions{});
  const auto one = strips(svg);
  REQUIRE(one.size() == 1);
  const Point O = circle_of(svg, "O"), Q = circle_of(svg, "Q");
  CHECK(one[0][0] < O.x());
  CHECK(one[0][2] > Q.x());
  CHECK(one[0][1] > O.y());  // below the pivots (SVG y grows downwards)
  // Klann's three pivots are at three heights: three strips, each under its pivot only.
  const Swept klann = shipped_model("klann");
  const std::string k_svg = numlab::cli::linkage_pose_svg(*klann.model, klann.sweep, 0, LinkageSceneOptions{});
  const auto three = strips(k_svg);
  REQUIRE(three.size() == 3);
  for (const char* pivot : {"A", "B", "D"}) {
    const Point p = circle_of(k_svg, pivot);
    CHECK(std::count_if(three.begin(), three.end(), [&](const auto& s) { return s[0] < p.x() && s[2] > p.x() && s[1] > p.y(); }) >= 1);
  }
}

TEST_CASE("A body whose points lie on one line is drawn as a bar through its outer points", "[scene][drawing]") {
  // The four-bar with its coupler a body A, B, P, P on the extension of A -> B (1.5 past B): a bar
  // with a point on its extension.
  LinkageDescription d = read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml");
  const int A = d.joint_index("A"), B = d.joint_index("B");
  const auto coupler = std::find_if(d.links.begin(), d.links.end(), [&](const LinkSpec& l) { return l.first == A && l.second == B; });
  REQUIRE(coupler != d.links.end());
  const double length = coupler->length;
  d.links.erase(coupler);
  JointSpec P;
  P.name = "P";
  const Point a = d.joints[static_cast<std::size_t>(A)].position, b = d.joints[static_cast<std::size_t>(B)].position;
  P.position = b + (b - a).normalized() * 1.5;
  d.joints.push_back(P);
  BodySpec bar;
  bar.name = "coupler";
  bar.joints = {A, B, static_cast<int>(d.joints.size()) - 1};
  bar.local = {{0.0, 0.0}, {length, 0.0}, {length + 1.5, 0.0}};
  d.bodies.push_back(bar);
  const Swept s = swept(d);
  REQUIRE(s.sweep.status == Status::converged);
  const std::size_t pose = *numlab::cli::best_conditioned_pose(*s.model, s.sweep);
  const std::string svg = numlab::cli::linkage_pose_svg(*s.model, s.sweep, pose, LinkageSceneOptions{});
  CHECK(count(svg, "<polygon class=\"body\"") == 0);
  REQUIRE(count(svg, "<line class=\"body\"") == 1);
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("<line class=\"body\" x1=\"([-0-9.]+)\" y1=\"([-0-9.]+)\" x2=\"([-0-9.]+)\" y2=\"([-0-9.]+)\"")));
  CHECK((Point(std::stod(m[1]), std::stod(m[2])) - circle_of(svg, "A")).norm() <= 2.0 * printed);
  CHECK((Point(std::stod(m[3]), std::stod(m[4])) - circle_of(svg, "P")).norm() <= 2.0 * printed);
  CHECK(crowded_names(svg) == "");
  // The animation moves the bar's two ends.
  const std::string animation = numlab::cli::linkage_animation_svg(*s.model, s.sweep, 4.0);
  CHECK(count(animation, "<line class=\"body\"") == 1);
  CHECK(count(animation, "<polygon class=\"body\"") == 0);
  // A body with a point off the line stays a polygon.
  d.bodies.back().local.back() = {length + 1.5, 0.5};
  d.joints.back().position += Point(a.y() - b.y(), b.x() - a.x()).normalized() * 0.5;
  const Swept plate = swept(d);
  REQUIRE(plate.sweep.status == Status::converged);
  CHECK(count(numlab::cli::linkage_pose_svg(*plate.model, plate.sweep, 0, LinkageSceneOptions{}), "<polygon class=\"body\"") == 1);
}
