#include "scenes/linkage_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "output/driver_units.hpp"
#include "output/svg_canvas.hpp"
#include "scenes/ground_drawing.hpp"
#include "scenes/label_placement.hpp"
#include "scenes/scene_layout.hpp"

namespace numlab::cli {

namespace {

using mechanisms::JointPositions;
using mechanisms::LinkageModel;
using mechanisms::LinkagePose;
using mechanisms::LinkageSweep;
using Point = Eigen::Vector2d;

constexpr const char* bar_colour = "#34495e";
constexpr const char* crank_colour = "#c0392b";
constexpr const char* path_colour = "#2471a3";
constexpr const char* arrow_colour = "#1e8449";
constexpr double arrow_share = 0.15;  // the longest velocity arrow, as a share of the frame's larger side

// What both scenes draw from: the converged poses in sweep order, drawn at `zoom` (a power of ten
// that makes the picture at least 10 units across, so that three decimals resolve it) with every
// size in `unit` (a hundredth of the larger side, as the Jansen leg's sizes are for its ~100 units).
struct Scene {
  const LinkageModel& model;
  std::vector<JointPositions> frames;   // joints of each converged pose, zoomed
  std::vector<std::size_t> sweep_index;  // the pose of each frame
  std::vector<bool> run_start;           // the pose before this one did not assemble
  std::size_t skipped = 0;               // poses that did not assemble
  bool closed = false;                   // the poses go once round the crank: paths close
  double zoom = 1.0, unit = 1.0;
};

bool assembled(const LinkageModel& model, const LinkagePose& pose) {
  return pose.outcome.status == Status::converged && pose.q.size() == model.unknown_count();
}

Scene scene_of(const LinkageModel& model, const LinkageSweep& sweep) {
  Scene scene{model, {}, {}, {}, 0, false, 1.0, 1.0};
  bool previous = true;
  for (std::size_t k = 0; k < sweep.poses.size(); ++k) {
    const bool ok = assembled(model, sweep.poses[k]);
    if (ok) {
      scene.frames.push_back(model.positions(sweep.poses[k].q));
      scene.sweep_index.push_back(k);
      scene.run_start.push_back(!previous || scene.frames.size() == 1);
    } else {
      ++scene.skipped;
    }
    previous = ok;
  }
  if (scene.frames.empty()) throw std::invalid_argument("no assembled pose to draw");
  std::vector<Point> points;
  for (const auto& joints : scene.frames) points.insert(points.end(), joints.begin(), joints.end());
  const double side = larger_side(frame_of(points));
  while (side * scene.zoom < 10.0 && scene.zoom < 1e12) scene.zoom *= 10.0;
  for (auto& joints : scene.frames) {
    for (Point& p : joints) p *= scene.zoom;
  }
  scene.unit = std::max(side * scene.zoom, 10.0) / 100.0;
  const auto& poses = sweep.poses;
  if (model.crank_driven() && scene.skipped == 0 && poses.size() > 2) {
    const double step = std::abs(poses[1].driver - poses[0].driver);
    scene.closed = std::abs(std::abs(poses.back().driver - poses.front().driver) + step - 360.0) < 1e-6;
  }
  return scene;
}

std::string title_of(const LinkageModel& model) {
  const auto& d = model.description();
  return xml_escaped(d.title.empty() ? d.name : d.title);
}

std::string driver_text(const mechanisms::DriverSpec& driver, double value) {
  switch (driver.kind) {
    case mechanisms::DriverKind::crank: return fmt::format("crank {:g} deg", value);
    case mechanisms::DriverKind::motor: return fmt::format("motor {:g} deg", value);
    case mechanisms::DriverKind::actuator: return fmt::format("actuator length {:g}", value);
    default: return fmt::format("slider travel {:g}", value);
  }
}
std::string driver_text(const LinkageModel& model, double value) { return driver_text(model.description().driver, value); }

// Every driver of the file: the first, and the second of a mechanism of mobility 2. Each is drawn
// as a driver (crank_colour), whichever it is.
std::vector<const mechanisms::DriverSpec*> drivers_of(const mechanisms::LinkageDescription& d) {
  std::vector<const mechanisms::DriverSpec*> drivers{&d.driver};
  if (d.second_driver) drivers.push_back(&*d.second_driver);
  return drivers;
}

// The second driver's value at a pose, for the caption: ", crank 90 deg held" in a sweep (which holds
// it at the model's value), ", crank 45 deg" on a --drivers path; "" with one driver.
std::string second_driver_text(const LinkageModel& model, const LinkagePose& pose) {
  const auto& second = model.description().second_driver;
  if (!second) return {};
  const bool held = std::isnan(pose.second_driver);
  return ", " + driver_text(*second, held ? model.second_driver() : pose.second_driver) + (held ? " held" : "");
}

std::size_t at(int joint) { return static_cast<std::size_t>(joint); }

// The SMIL values over the frames from `first`, once round and back to `first`.
template <typename Value>
std::string values(const Scene& scene, std::size_t first, Value value) {
  std::string list;
  for (std::size_t k = 0; k <= scene.frames.size(); ++k) list += value(scene.frames[(first + k) % scene.frames.size()]) + ";";
  list.pop_back();
  return list;
}

// An attribute moving through those values, `seconds` per pass; nothing when the picture stands still.
template <typename Value>
std::string animate(const Scene& scene, std::size_t first, double seconds, const char* attribute, Value value) {
  if (seconds <= 0.0) return {};
  return fmt::format("<animate attributeName=\"{}\" dur=\"{:.3f}s\" repeatCount=\"indefinite\" values=\"{}\"/>",
                     attribute, seconds, values(scene, first, value));
}

std::string coordinate(double value) { return fmt::format("{:.3f}", value); }

// Each slider's line, dashed across the frame (clipped to it).
std::string slider_guides(const Scene& scene, const Frame& frame) {
  std::string svg;
  for (const auto& slider : scene.model.description().sliders) {
    if (slider.on_link()) continue;  // a slot moves with its link, which is drawn: no fixed line
    const double angle = slider.angle_deg * std::numbers::pi / 180.0;
    const Point u(std::cos(angle), std::sin(angle)), through = slider.through * scene.zoom;
    Point a, b;
    if (!line_across(frame, through, u, a, b)) continue;
    svg += fmt::format("<line class=\"guide\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"#888\" "
                       "stroke-width=\"{:.3g}\" stroke-dasharray=\"{:.3g} {:.3g}\"/>\n",
                       a.x(), -a.y(), b.x(), -b.y(), 0.4 * scene.unit, 3 * scene.unit, 1.5 * scene.unit);
  }
  return svg;
}

// The length of each joint's path over the frames (within runs of assembled poses).
std::vector<double> path_lengths(const Scene& scene) {
  std::vector<double> length(scene.frames[0].size(), 0.0);
  for (std::size_t k = 1; k < scene.frames.size(); ++k) {
    if (scene.run_start[k]) continue;
    for (std::size_t j = 0; j < length.size(); ++j) length[j] += (scene.frames[k][j] - scene.frames[k - 1][j]).norm();
  }
  return length;
}

// The joints whose paths are drawn and the one drawn heavier: the chosen ones, all heavier; else every
// moving joint, the longest path heavier (not counting a crank pin's circle, of either driver, when
// there is another).
struct DrawnPaths {
  std::vector<int> joints;
  int heavy = -1;  // -1: every drawn path is heavy (they were chosen)
};
DrawnPaths drawn_paths(const Scene& scene, const LinkageSceneOptions& options) {
  if (!options.paths.empty()) return {options.paths, -1};
  const std::vector<double> length = path_lengths(scene);
  const auto& moving = scene.model.moving();
  const auto drivers = drivers_of(scene.model.description());
  auto crank_pin = [&](int j) {
    return std::any_of(drivers.begin(), drivers.end(), [j](const mechanisms::DriverSpec* d) { return d->angle() && d->joint == j; });
  };
  std::vector<int> candidates;
  for (const int j : moving) {
    if (!crank_pin(j)) candidates.push_back(j);
  }
  if (candidates.empty()) candidates = moving;
  const int longest = *std::max_element(candidates.begin(), candidates.end(), [&](int a, int b) { return length[at(a)] < length[at(b)]; });
  return {moving, longest};
}

// Dashed, the drawn paths (id "path-NAME"), the heavy ones heavier.
std::string joint_paths(const Scene& scene, const DrawnPaths& paths) {
  std::string svg;
  for (const int j : paths.joints) {
    std::string d;
    for (std::size_t k = 0; k < scene.frames.size(); ++k) {
      const Point& p = scene.frames[k][at(j)];
      d += fmt::format("{} {:.3f} {:.3f} ", scene.run_start[k] ? "M" : "L", p.x(), -p.y());
    }
    if (scene.closed) d += "Z";
    const bool heavy = paths.heavy < 0 || j == paths.heavy;
    svg += fmt::format("<path class=\"path\" id=\"path-{}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.3g}\" "
                       "stroke-dasharray=\"{:.3g} {:.3g}\"/>\n",
                       xml_escaped(scene.model.description().joints[at(j)].name), d, heavy ? path_colour : "#7fa7c9",
                       (heavy ? 0.8 : 0.45) * scene.unit, 2 * scene.unit, 1.5 * scene.unit);
  }
  return svg;
}

// The ground joints' positions in the scene (zoomed).
std::vector<Point> ground_pivots(const Scene& scene) {
  std::vector<Point> pivots;
  for (const auto& joint : scene.model.description().joints) {
    if (joint.ground) pivots.push_back(joint.position * scene.zoom);
  }
  return pivots;
}

// An actuator driver (a hydraulic cylinder from `from` to `joint`): a heavy barrel over the first
// half of the current length and a thinner rod the whole way, both moving with the two joints.
// `number` is the driver's (1 or 2), in data-driver.
std::string actuator(const Scene& scene, const mechanisms::DriverSpec& driver, int number, std::size_t first, double seconds) {
  if (driver.kind != mechanisms::DriverKind::actuator) return {};
  const double u = scene.unit;
  auto end = [&](const JointPositions& f, double share) { return Point(f[at(driver.from)] + share * (f[at(driver.joint)] - f[at(driver.from)])); };
  std::string svg;
  for (const double share : {1.0, 0.5}) {  // the rod, then the barrel over it
    auto x = [&](const JointPositions& f) { return coordinate(end(f, share).x()); };
    auto y = [&](const JointPositions& f) { return coordinate(-end(f, share).y()); };
    const Point a = scene.frames[first][at(driver.from)], b = end(scene.frames[first], share);
    svg += fmt::format("<line class=\"actuator\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" stroke-linecap=\"butt\" data-driver=\"{}\">{}{}{}{}</line>\n",
                       a.x(), -a.y(), b.x(), -b.y(), share < 1.0 ? crank_colour : "#7b8a8b", (share < 1.0 ? 3.5 : 1.4) * u, number,
                       animate(scene, first, seconds, "x1", [&](const JointPositions& f) { return coordinate(f[at(driver.from)].x()); }),
                       animate(scene, first, seconds, "y1", [&](const JointPositions& f) { return coordinate(-f[at(driver.from)].y()); }),
                       animate(scene, first, seconds, "x2", x), animate(scene, first, seconds, "y2", y));
  }
  return svg;
}

// The number (1 or 2) of the crank or motor that turns the bar or body holding `joints` (its pivot
// and its joint both among them), or 0.
int turning_driver(const mechanisms::LinkageDescription& d, const std::vector<int>& joints) {
  const auto drivers = drivers_of(d);
  for (std::size_t k = 0; k < drivers.size(); ++k) {
    const auto& driver = *drivers[k];
    if (driver.angle() && std::count(joints.begin(), joints.end(), driver.pivot) > 0 &&
        std::count(joints.begin(), joints.end(), driver.joint) > 0) {
      return static_cast<int>(k) + 1;
    }
  }
  return 0;
}

// The number (1 or 2) of the slider driver that moves slider `s`, or 0.
int sliding_driver(const mechanisms::LinkageDescription& d, std::size_t s) {
  const auto drivers = drivers_of(d);
  for (std::size_t k = 0; k < drivers.size(); ++k) {
    if (drivers[k]->kind == mechanisms::DriverKind::slider && drivers[k]->slider == static_cast<int>(s)) return static_cast<int>(k) + 1;
  }
  return 0;
}

// ` data-driver="N"` on a driver's element, nothing on the others.
std::string driver_mark(int number) { return number > 0 ? fmt::format(" data-driver=\"{}\"", number) : std::string(); }

// A slot's block turns with its line line_from -> line_to: its SVG angle (clockwise, so minus the
// model's) at each frame from `first`, once round and back, each within half a turn of the one
// before, so that SMIL never spins the block the long way between two frames.
std::string slot_angles(const Scene& scene, const mechanisms::SliderSpec& slider, std::size_t first) {
  std::string list;
  double previous = 0.0;
  for (std::size_t k = 0; k <= scene.frames.size(); ++k) {
    const JointPositions& f = scene.frames[(first + k) % scene.frames.size()];
    const Point along = f[at(slider.line_to)] - f[at(slider.line_from)];
    double angle = 0.0 - std::atan2(along.y(), along.x()) * 180.0 / std::numbers::pi;  // 0, not -0
    if (k > 0) angle -= 360.0 * std::round((angle - previous) / 360.0);
    list += fmt::format("{:.6f};", angle);
    previous = angle;
  }
  list.pop_back();
  return list;
}

// The linkage at frames[first]: bodies, links, slider blocks, joints; with seconds > 0 it moves
// through every frame. Every driver is drawn as one: a crank's or motor's bar or body in
// crank_colour and heavier, a slider driver's block pink, an actuator as a cylinder.
std::string linkage(const Scene& scene, std::size_t first, double seconds) {
  const auto& d = scene.model.description();
  const auto& now = scene.frames[first];
  const double u = scene.unit;
  auto x_of = [](int j) { return [j](const JointPositions& f) { return coordinate(f[at(j)].x()); }; };
  auto y_of = [](int j) { return [j](const JointPositions& f) { return coordinate(-f[at(j)].y()); }; };
  std::string svg = ground_svg(ground_pivots(scene), u);
  for (const auto& body : d.bodies) {
    const int number = turning_driver(d, body.joints);
    const bool driven = number > 0;
    int first_end = -1, second_end = -1;
    if (body_on_one_line(body, first_end, second_end)) {  // a bar with points on it: its outer points
      const Point &a = now[at(first_end)], &b = now[at(second_end)];
      svg += fmt::format("<line class=\"body\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                         "stroke-width=\"{:.3g}\" stroke-linecap=\"round\"{}>{}{}{}{}</line>\n",
                         a.x(), -a.y(), b.x(), -b.y(), driven ? crank_colour : bar_colour, (driven ? 3.0 : 2.0) * u, driver_mark(number),
                         animate(scene, first, seconds, "x1", x_of(first_end)), animate(scene, first, seconds, "y1", y_of(first_end)),
                         animate(scene, first, seconds, "x2", x_of(second_end)), animate(scene, first, seconds, "y2", y_of(second_end)));
      continue;
    }
    const std::vector<int> hull = body_outline(body);
    auto points = [&](const JointPositions& f) {
      std::string list;
      for (const int j : hull) list += fmt::format("{:.3f},{:.3f} ", f[at(j)].x(), -f[at(j)].y());
      list.pop_back();
      return list;
    };
    svg += fmt::format("<polygon class=\"body\" points=\"{}\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" stroke-linejoin=\"round\"{}>{}</polygon>\n",
                       points(now), driven ? "#f1948a" : "#aab7c4", driven ? crank_colour : bar_colour, 1.2 * u, driver_mark(number),
                       animate(scene, first, seconds, "points", points));
  }
  std::vector<std::size_t> order;  // the links, the drivers' last (over a link they lie along)
  for (const bool driving : {false, true}) {
    for (std::size_t k = 0; k < d.links.size(); ++k) {
      if ((turning_driver(d, {d.links[k].first, d.links[k].second}) > 0) == driving) order.push_back(k);
    }
  }
  for (const std::size_t k : order) {
    const auto& link = d.links[k];
    const int number = turning_driver(d, {link.first, link.second});
    const bool heavy = number > 0;
    const Point &a = now[at(link.first)], &b = now[at(link.second)];
    svg += fmt::format("<line class=\"link\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" stroke-linecap=\"round\"{}>{}{}{}{}</line>\n",
                       a.x(), -a.y(), b.x(), -b.y(), heavy ? crank_colour : bar_colour, (heavy ? 3.0 : 2.0) * u, driver_mark(number),
                       animate(scene, first, seconds, "x1", x_of(link.first)),
                       animate(scene, first, seconds, "y1", y_of(link.first)),
                       animate(scene, first, seconds, "x2", x_of(link.second)),
                       animate(scene, first, seconds, "y2", y_of(link.second)));
  }
  const auto drivers = drivers_of(d);
  for (std::size_t k = 0; k < drivers.size(); ++k) svg += actuator(scene, *drivers[k], static_cast<int>(k) + 1, first, seconds);
  for (std::size_t s = 0; s < d.sliders.size(); ++s) {
    const auto& slider = d.sliders[s];
    const int number = sliding_driver(d, s);
    const bool driven = number > 0;
    const Point& p = now[at(slider.joint)];
    // A block in a slot lies along its link's line B -> C at this pose; on a fixed line, along it.
    const Point along = slider.on_link() ? Point(now[at(slider.line_to)] - now[at(slider.line_from)]) : Point(1.0, 0.0);
    const double turn_deg = slider.on_link() ? std::atan2(along.y(), along.x()) * 180.0 / std::numbers::pi : slider.angle_deg;
    auto place = [&](const JointPositions& f) { return fmt::format("{:.3f},{:.3f}", f[at(slider.joint)].x(), -f[at(slider.joint)].y()); };
    const std::string moving =
        seconds > 0.0 ? fmt::format("<animateTransform attributeName=\"transform\" type=\"translate\" dur=\"{:.3f}s\" "
                                    "repeatCount=\"indefinite\" values=\"{}\"/>",
                                    seconds, values(scene, first, place))
                      : std::string();
    // A block in a slot also turns with its line, frame by frame.
    const std::string turning =
        seconds > 0.0 && slider.on_link()
            ? fmt::format("<animateTransform attributeName=\"transform\" type=\"rotate\" dur=\"{:.3f}s\" "
                          "repeatCount=\"indefinite\" values=\"{}\"/>",
                          seconds, slot_angles(scene, slider, first))
            : std::string();
    svg += fmt::format("<g class=\"slider\" transform=\"translate({:.3f},{:.3f})\"{}>{}<rect x=\"{:.3g}\" y=\"{:.3g}\" "
                       "width=\"{:.3g}\" height=\"{:.3g}\" transform=\"rotate({:.6f})\" fill=\"{}\" stroke=\"#222\" "
                       "stroke-width=\"{:.3g}\">{}</rect></g>\n",
                       p.x(), -p.y(), driver_mark(number), moving, -4.0 * u, -2.5 * u, 8.0 * u, 5.0 * u, 0.0 - turn_deg,
                       driven ? "#f1948a" : "#d5dbdb", 0.5 * u, turning);
  }
  for (std::size_t j = 0; j < now.size(); ++j) {
    svg += fmt::format("<circle id=\"joint-{}\" cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3g}\" fill=\"white\" stroke=\"#222\" "
                       "stroke-width=\"{:.3g}\">{}{}</circle>\n",
                       xml_escaped(d.joints[j].name), now[j].x(), -now[j].y(), 1.6 * u, 0.7 * u,
                       animate(scene, first, seconds, "cx", x_of(static_cast<int>(j))),
                       animate(scene, first, seconds, "cy", y_of(static_cast<int>(j))));
  }
  return svg;
}

constexpr double name_size = 4.5;  // font size of the joints' names, in units

// A name's half extent: 0.35 em per character (Helvetica's widest capitals are about 0.72 em) and
// half an em up and down.
Point name_half(const std::string& name, double unit) {
  const double em = name_size * unit;
  return {0.35 * em * static_cast<double>(name.size()), 0.5 * em};
}

// What the names keep clear of (label_placement.hpp): the joints' circles and slider blocks, the
// links and the bodies (edges and spokes to their centre, so that a name does not sit inside one),
// the ground, the slider lines, the arrows; the drawn paths count less.
LabelObstacles label_obstacles(const Scene& scene, const JointPositions& now, const std::vector<int>& paths,
                               const std::vector<std::pair<Point, Point>>& arrows) {
  const auto& d = scene.model.description();
  const double u = scene.unit;
  LabelObstacles obstacles;
  for (const Point& p : now) obstacles.discs.push_back({p, 2.0 * u});
  for (const auto& slider : d.sliders) obstacles.discs.push_back({now[at(slider.joint)], 4.8 * u});
  for (const auto& link : d.links) obstacles.segments.push_back({now[at(link.first)], now[at(link.second)], 1.5 * u, false});
  for (const auto& body : d.bodies) {
    int a = -1, b = -1;
    if (body_on_one_line(body, a, b)) {
      obstacles.segments.push_back({now[at(a)], now[at(b)], 1.5 * u, false});
      continue;
    }
    const std::vector<int> hull = body_outline(body);
    Point centre = Point::Zero();
    for (const int j : hull) centre += now[at(j)] / static_cast<double>(hull.size());
    for (std::size_t k = 0; k < hull.size(); ++k) {
      obstacles.segments.push_back({now[at(hull[k])], now[at(hull[(k + 1) % hull.size()])], 0.6 * u, false});
      obstacles.segments.push_back({now[at(hull[k])], centre, 0.0, false});
    }
  }
  obstacles.boxes = ground_boxes(ground_pivots(scene), u);
  for (const mechanisms::DriverSpec* driver : drivers_of(d)) {
    if (driver->kind != mechanisms::DriverKind::actuator) continue;
    obstacles.segments.push_back({now[at(driver->from)], now[at(driver->joint)], 1.8 * u, false});
  }
  double side = 0.0;
  for (const auto& frame : scene.frames) {
    for (const Point& p : frame) side = std::max(side, p.norm());
  }
  for (const auto& slider : d.sliders) {
    if (slider.on_link()) continue;  // its line is its link's, already an obstacle
    const double angle = slider.angle_deg * std::numbers::pi / 180.0;
    const Point direction(std::cos(angle), std::sin(angle)), through = slider.through * scene.zoom;
    const Point middle = through + direction * direction.dot(now[at(slider.joint)] - through);
    obstacles.segments.push_back({middle - 4.0 * side * direction, middle + 4.0 * side * direction, 0.2 * u, true});
  }
  for (const auto& [from, to] : arrows) obstacles.segments.push_back({from, to, 0.4 * u, false});
  // The paths, at most about 120 pieces each.
  for (const int j : paths) {
    const std::size_t stride = std::max<std::size_t>(1, scene.frames.size() / 120);
    for (std::size_t k = stride; k < scene.frames.size(); k += stride) {
      if (scene.run_start[k]) continue;
      obstacles.segments.push_back({scene.frames[k - stride][at(j)], scene.frames[k][at(j)], 0.4 * u, true});
    }
  }
  return obstacles;
}

// Each joint's name box (label_placement.hpp).
std::vector<LabelBox> label_places(const Scene& scene, const JointPositions& now, const std::vector<int>& paths,
                                   const std::vector<std::pair<Point, Point>>& arrows) {
  std::vector<Point> halves;
  for (const auto& joint : scene.model.description().joints) halves.push_back(name_half(joint.name, scene.unit));
  return place_labels(std::vector<Point>(now.begin(), now.end()), halves, 2.0 * scene.unit,
                      label_obstacles(scene, now, paths, arrows), scene.unit);
}

// Each joint's name, centred in its box.
std::string joint_names(const Scene& scene, const std::vector<LabelBox>& places) {
  const auto& joints = scene.model.description().joints;
  std::string svg;
  for (std::size_t j = 0; j < places.size(); ++j) {
    svg += fmt::format("<text class=\"name\" x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"{:.3g}\" fill=\"#222\" text-anchor=\"middle\" "
                       "dominant-baseline=\"central\">{}</text>\n",
                       places[j].centre.x(), -places[j].centre.y(), name_size * scene.unit, xml_escaped(joints[j].name));
  }
  return svg;
}

// The frame grown to hold every name's box.
void include_names(Frame& frame, const std::vector<LabelBox>& places) {
  for (const LabelBox& box : places) {
    include(frame, box.centre - box.half);
    include(frame, box.centre + box.half);
  }
}

// The slider guides run across the frame and its side and bottom margins (Frame::header's).
std::string guides_across(const Scene& scene, const Frame& frame) {
  const double margin = 12.0 * scene.unit;
  return slider_guides(scene, Frame{frame.min_x - margin, frame.max_x + margin, frame.min_y - margin, frame.max_y});
}

// The header, the caption, the arrowhead and the drawing, in a frame fitted to the caption.
std::string picture(const Scene& scene, const Frame& frame, const Caption& caption, const std::string& drawing) {
  const double u = scene.unit;
  const double width = frame.max_x - frame.min_x + 24.0 * u, height = frame.max_y - frame.min_y + 32.0 * u;
  std::string svg = frame.header(std::min(900.0, 700.0 * width / height), u) + caption.svg(frame);
  svg += fmt::format("<defs><marker id=\"velocity-head\" viewBox=\"0 0 10 10\" refX=\"8\" refY=\"5\" markerWidth=\"4\" "
                     "markerHeight=\"4\" orient=\"auto\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"{}\"/></marker></defs>\n",
                     arrow_colour);
  return svg + drawing + "</svg>\n";
}

std::string skipped_line(const Scene& scene, const LinkageSweep& sweep) {
  return fmt::format("{} of {} poses did not assemble and are skipped", scene.skipped, sweep.poses.size());
}

std::string paths_caption(const Scene& scene, const DrawnPaths& paths, const LinkageSceneOptions& options) {
  const auto& joints = scene.model.description().joints;
  if (paths.heavy < 0) {
    std::vector<std::string> names;
    for (const int j : paths.joints) names.push_back(xml_escaped(joints[at(j)].name));
    return fmt::format("dashed: the path{} of {} over {} assembled poses ({})", names.size() == 1 ? "" : "s",
                       fmt::join(names, ", "), scene.frames.size(), xml_escaped(options.paths_from));
  }
  const auto drivers = drivers_of(scene.model.description());
  const auto pins = std::count_if(drivers.begin(), drivers.end(), [](const mechanisms::DriverSpec* d) { return d->angle(); });
  return fmt::format("dashed: the joints' paths over {} assembled poses; heavier: {}'s, the longest{}", scene.frames.size(),
                     xml_escaped(joints[at(paths.heavy)].name),
                     pins == 0 ? "" : pins == 1 ? " but the crank pin's" : " but the crank pins'");
}

// Each moving joint's velocity as an arrow from the joint, the longest arrow_share of the frame's
// larger side; the frame grows to hold the tips and the caption states the scale. A velocity that is
// missing or not finite (a singular J) is said so, not drawn. Each arrow's ends go to `drawn`.
std::string arrows_at(const Scene& scene, const JointPositions& now, const Eigen::VectorXd& v, Frame& frame,
                      Caption& caption, std::vector<std::pair<Point, Point>>& drawn) {
  const LinkageModel& model = scene.model;
  if (v.size() != model.unknown_count() || !v.allFinite()) {
    caption.lines.emplace_back("arrows: the velocity at this pose is not finite (J is singular); none drawn");
    return {};
  }
  auto velocity_of = [&](std::size_t k) {
    return Point(v[static_cast<Eigen::Index>(2 * k)], v[static_cast<Eigen::Index>(2 * k + 1)]);
  };
  double fastest = 0.0;
  for (std::size_t k = 0; k < model.moving().size(); ++k) fastest = std::max(fastest, velocity_of(k).norm());
  if (fastest == 0.0) {
    caption.lines.emplace_back("arrows: every joint is at rest at this pose");
    return {};
  }
  const double scale = arrow_share * larger_side(frame) / scene.zoom / fastest;  // model length per unit of velocity
  std::string svg;
  for (std::size_t k = 0; k < model.moving().size(); ++k) {
    if (velocity_of(k).norm() == 0.0) continue;
    const Point& from = now[at(model.moving()[k])];
    const Point to = from + velocity_of(k) * scale * scene.zoom;
    include(frame, to);
    drawn.emplace_back(from, to);
    svg += fmt::format("<line class=\"velocity\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" marker-end=\"url(#velocity-head)\"/>\n",
                       from.x(), -from.y(), to.x(), -to.y(), arrow_colour, 0.7 * scene.unit);
  }
  caption.lines.push_back(fmt::format("arrows: velocity per {}{}; an arrow 1 unit long stands for {:.3g} units per {}",
                                      velocity_per(model.driver_kind()),
                                      model.has_second_driver() ? " (the second driver held: partial derivatives)" : "",
                                      1.0 / scale, model.crank_driven() ? "radian" : "unit of the driver"));
  return svg;
}

// Every chosen path must be a moving joint's.
void check_paths(const LinkageModel& model, const LinkageSceneOptions& options) {
  for (const int j : options.paths) {
    if (std::find(model.moving().begin(), model.moving().end(), j) == model.moving().end()) {
      throw std::invalid_argument(fmt::format("joint {} has no path to draw: it is not a moving joint", j));
    }
  }
}

}  // namespace

std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, const LinkageSceneOptions& options) {
  if (pose >= sweep.poses.size()) throw std::invalid_argument(fmt::format("no pose {} in the sweep", pose));
  if (!assembled(model, sweep.poses[pose])) {
    throw std::invalid_argument(fmt::format("the pose at {} did not assemble", driver_text(model, sweep.poses[pose].driver)));
  }
  check_paths(model, options);
  const Scene scene = scene_of(model, sweep);
  const std::size_t first = static_cast<std::size_t>(
      std::find(scene.sweep_index.begin(), scene.sweep_index.end(), pose) - scene.sweep_index.begin());
  const JointPositions& now = scene.frames[first];
  std::vector<Point> points;
  for (const auto& joints : scene.frames) points.insert(points.end(), joints.begin(), joints.end());
  Frame frame = frame_of(points);

  const std::string reason = options.pose_reason.empty() ? "" : " (" + xml_escaped(options.pose_reason) + ")";
  Caption caption{{fmt::format("{} at {}{}{}", title_of(model), driver_text(model, sweep.poses[pose].driver),
                               second_driver_text(model, sweep.poses[pose]), reason)},
                  scene.unit};
  const DrawnPaths paths = drawn_paths(scene, options);
  std::string drawing = joint_paths(scene, paths);
  caption.lines.push_back(paths_caption(scene, paths, options));
  if (scene.skipped > 0) caption.lines.push_back(skipped_line(scene, sweep));

  const Eigen::VectorXd& velocity = sweep.poses[pose].velocity;
  std::vector<std::pair<Point, Point>> arrow_ends;
  const std::string arrows = options.velocity_arrows ? arrows_at(scene, now, velocity, frame, caption, arrow_ends) : std::string();
  const std::vector<int> heavy = paths.heavy < 0 ? paths.joints : std::vector<int>{paths.heavy};
  const std::vector<LabelBox> places = label_places(scene, now, heavy, arrow_ends);
  include_names(frame, places);
  frame = caption.fitted(frame);
  drawing = guides_across(scene, frame) + drawing + linkage(scene, first, 0.0);
  // The arrows over everything (a joint's circle would hide an arrow's tail), then the names.
  drawing += arrows + joint_names(scene, places);
  return picture(scene, frame, caption, drawing);
}

std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, bool velocity_arrows) {
  LinkageSceneOptions options;
  options.velocity_arrows = velocity_arrows;
  return linkage_pose_svg(model, sweep, pose, options);
}

std::string linkage_animation_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                                  double seconds, const LinkageSceneOptions& options) {
  check_paths(model, options);
  const Scene scene = scene_of(model, sweep);
  std::vector<Point> points;
  for (const auto& joints : scene.frames) points.insert(points.end(), joints.begin(), joints.end());
  Frame frame = frame_of(points);
  const auto& first = sweep.poses[scene.sweep_index.front()], &last = sweep.poses[scene.sweep_index.back()];
  // A sweep holds the second driver (say at what); a --drivers path moves both.
  const std::string second = !model.has_second_driver() || std::isnan(first.second_driver) ? second_driver_text(model, first)
                                                                                             : ", both drivers along a path";
  Caption caption{{fmt::format("{}, {} poses from {} to {}{}", title_of(model), scene.frames.size(),
                               driver_text(model, first.driver), model.crank_driven() ? fmt::format("{:g} deg", last.driver)
                                                                                      : fmt::format("{:g}", last.driver),
                               second)},
                  scene.unit};
  const DrawnPaths paths = drawn_paths(scene, options);
  std::string drawing = joint_paths(scene, paths);
  caption.lines.push_back(paths_caption(scene, paths, options));
  caption.lines.push_back(scene.skipped > 0 ? skipped_line(scene, sweep) : std::string("every pose of the sweep assembled"));
  frame = caption.fitted(frame);
  drawing = guides_across(scene, frame) + drawing + linkage(scene, 0, seconds);
  return picture(scene, frame, caption, drawing);
}

std::optional<std::size_t> best_conditioned_pose(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep) {
  std::optional<std::size_t> best, first;
  for (std::size_t k = 0; k < sweep.poses.size(); ++k) {
    const LinkagePose& pose = sweep.poses[k];
    if (!assembled(model, pose)) continue;
    if (!first) first = k;
    if (std::isfinite(pose.condition) && (!best || pose.condition < sweep.poses[*best].condition)) best = k;
  }
  return best ? best : first;
}

std::optional<std::size_t> pose_at(const mechanisms::LinkageSweep& sweep, double value) {
  const auto& poses = sweep.poses;
  const double step = poses.size() > 1 ? std::abs(poses[1].driver - poses[0].driver) : 1.0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    if (std::abs(poses[k].driver - value) <= 1e-9 * std::max(step, 1e-300)) return k;
  }
  return std::nullopt;
}

}  // namespace numlab::cli
