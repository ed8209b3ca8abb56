#include "scenes/linkage_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "output/svg_canvas.hpp"
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

std::string driver_text(const LinkageModel& model, double value) {
  return model.crank_driven() ? fmt::format("crank {:g} deg", value) : fmt::format("slider travel {:g}", value);
}

std::size_t at(int joint) { return static_cast<std::size_t>(joint); }

// The joints each joint shares a link or a body with.
std::vector<std::vector<int>> neighbours(const LinkageModel& model) {
  const auto& d = model.description();
  std::vector<std::vector<int>> next(d.joints.size());
  for (const auto& link : d.links) {
    next[at(link.first)].push_back(link.second);
    next[at(link.second)].push_back(link.first);
  }
  for (const auto& body : d.bodies) {
    for (const int a : body.joints) {
      for (const int b : body.joints) {
        if (a != b) next[at(a)].push_back(b);
      }
    }
  }
  return next;
}

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

// Dashed, the path of every moving joint; the longest a little heavier (not counting the crank pin's
// circle when there is another). Returns the longest's name too.
std::string joint_paths(const Scene& scene, std::string& longest_name) {
  const std::vector<double> length = path_lengths(scene);
  const auto& moving = scene.model.moving();
  const auto& driver = scene.model.description().driver;
  std::vector<int> candidates;
  for (const int j : moving) {
    if (!(scene.model.crank_driven() && j == driver.joint)) candidates.push_back(j);
  }
  if (candidates.empty()) candidates = moving;
  const int longest = *std::max_element(candidates.begin(), candidates.end(), [&](int a, int b) { return length[at(a)] < length[at(b)]; });
  longest_name = xml_escaped(scene.model.description().joints[at(longest)].name);
  std::string svg;
  for (const int j : moving) {
    std::string d;
    for (std::size_t k = 0; k < scene.frames.size(); ++k) {
      const Point& p = scene.frames[k][at(j)];
      d += fmt::format("{} {:.3f} {:.3f} ", scene.run_start[k] ? "M" : "L", p.x(), -p.y());
    }
    if (scene.closed) d += "Z";
    const bool heavy = j == longest;
    svg += fmt::format("<path class=\"path\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.3g}\" "
                       "stroke-dasharray=\"{:.3g} {:.3g}\"/>\n",
                       d, heavy ? path_colour : "#7fa7c9", (heavy ? 0.8 : 0.45) * scene.unit, 2 * scene.unit,
                       1.5 * scene.unit);
  }
  return svg;
}

// A ground joint: the fixed pivot's triangle with a short hatched ground line under it.
std::string ground_pivot(const Point& p, double unit) {
  std::string svg = fixed_pivot(p, unit);
  const double y = -p.y() + 6.0 * unit;
  svg += fmt::format("<path d=\"M {:.3f} {:.3f} h {:.3f}", p.x() - 5.0 * unit, y, 10.0 * unit);
  for (int k = 0; k < 5; ++k) svg += fmt::format(" M {:.3f} {:.3f} l {:.3f} {:.3f}", p.x() - 4.0 * unit + 2.0 * k * unit, y, -1.5 * unit, 2.0 * unit);
  return svg + fmt::format("\" stroke=\"#666\" stroke-width=\"{:.3g}\" fill=\"none\"/>\n", 0.4 * unit);
}

// The linkage at frames[first]: bodies, links, slider blocks, joints; with seconds > 0 it moves
// through every frame.
std::string linkage(const Scene& scene, std::size_t first, double seconds) {
  const auto& d = scene.model.description();
  const auto& now = scene.frames[first];
  const double u = scene.unit;
  auto x_of = [](int j) { return [j](const JointPositions& f) { return coordinate(f[at(j)].x()); }; };
  auto y_of = [](int j) { return [j](const JointPositions& f) { return coordinate(-f[at(j)].y()); }; };
  const bool crank = scene.model.crank_driven();
  auto is_crank = [&](int a, int b) {
    const int pivot = d.driver.pivot, joint = d.driver.joint;
    return crank && ((a == pivot && b == joint) || (a == joint && b == pivot));
  };
  std::string svg;
  for (const auto& joint : d.joints) {
    if (joint.ground) svg += ground_pivot(joint.position * scene.zoom, u);
  }
  for (const auto& body : d.bodies) {
    const std::vector<int> hull = body_outline(body);
    const bool driven = crank && std::count(body.joints.begin(), body.joints.end(), d.driver.pivot) > 0 &&
                        std::count(body.joints.begin(), body.joints.end(), d.driver.joint) > 0;
    auto points = [&](const JointPositions& f) {
      std::string list;
      for (const int j : hull) list += fmt::format("{:.3f},{:.3f} ", f[at(j)].x(), -f[at(j)].y());
      list.pop_back();
      return list;
    };
    svg += fmt::format("<polygon class=\"body\" points=\"{}\" fill=\"{}\" fill-opacity=\"0.35\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" stroke-linejoin=\"round\">{}</polygon>\n",
                       points(now), driven ? "#f1948a" : "#aab7c4", driven ? crank_colour : bar_colour, 1.2 * u,
                       animate(scene, first, seconds, "points", points));
  }
  for (const auto& link : d.links) {
    const bool heavy = is_crank(link.first, link.second);
    const Point &a = now[at(link.first)], &b = now[at(link.second)];
    svg += fmt::format("<line class=\"link\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" stroke-linecap=\"round\">{}{}{}{}</line>\n",
                       a.x(), -a.y(), b.x(), -b.y(), heavy ? crank_colour : bar_colour, (heavy ? 3.0 : 2.0) * u,
                       animate(scene, first, seconds, "x1", x_of(link.first)),
                       animate(scene, first, seconds, "y1", y_of(link.first)),
                       animate(scene, first, seconds, "x2", x_of(link.second)),
                       animate(scene, first, seconds, "y2", y_of(link.second)));
  }
  for (std::size_t s = 0; s < d.sliders.size(); ++s) {
    const auto& slider = d.sliders[s];
    const bool driven = !crank && d.driver.slider == static_cast<int>(s);
    const Point& p = now[at(slider.joint)];
    auto place = [&](const JointPositions& f) { return fmt::format("{:.3f},{:.3f}", f[at(slider.joint)].x(), -f[at(slider.joint)].y()); };
    const std::string moving =
        seconds > 0.0 ? fmt::format("<animateTransform attributeName=\"transform\" type=\"translate\" dur=\"{:.3f}s\" "
                                    "repeatCount=\"indefinite\" values=\"{}\"/>",
                                    seconds, values(scene, first, place))
                      : std::string();
    svg += fmt::format("<g class=\"slider\" transform=\"translate({:.3f},{:.3f})\">{}<rect x=\"{:.3g}\" y=\"{:.3g}\" "
                       "width=\"{:.3g}\" height=\"{:.3g}\" transform=\"rotate({:.6g})\" fill=\"{}\" stroke=\"#222\" "
                       "stroke-width=\"{:.3g}\"/></g>\n",
                       p.x(), -p.y(), moving, -4.0 * u, -2.5 * u, 8.0 * u, 5.0 * u, -slider.angle_deg,
                       driven ? "#f1948a" : "#d5dbdb", 0.5 * u);
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

// Where each joint's name goes: of sixteen directions around the joint, the one farthest (in angle)
// from everything drawn at it: its links and bodies, its path (along the velocity, both ways), its
// slider's line, a ground pivot's triangle below it.
std::vector<Point> label_places(const Scene& scene, const JointPositions& now, const Eigen::VectorXd& velocity) {
  const auto& d = scene.model.description();
  const auto next = neighbours(scene.model);
  std::vector<std::vector<Point>> taken(now.size());
  for (std::size_t j = 0; j < now.size(); ++j) {
    for (const int n : next[j]) {
      if ((now[at(n)] - now[j]).norm() > 0.0) taken[j].push_back((now[at(n)] - now[j]).normalized());
    }
    if (d.joints[j].ground) taken[j].insert(taken[j].end(), {Point(0.0, -1.0), Point(0.5, -1.0).normalized(), Point(-0.5, -1.0).normalized()});
  }
  for (std::size_t k = 0; velocity.size() == scene.model.unknown_count() && k < scene.model.moving().size(); ++k) {
    const Point v(velocity[static_cast<Eigen::Index>(2 * k)], velocity[static_cast<Eigen::Index>(2 * k + 1)]);
    if (v.norm() > 0.0) taken[at(scene.model.moving()[k])].insert(taken[at(scene.model.moving()[k])].end(), {v.normalized(), -v.normalized()});
  }
  for (const auto& slider : d.sliders) {
    const double angle = slider.angle_deg * std::numbers::pi / 180.0;
    const Point u(std::cos(angle), std::sin(angle));
    taken[at(slider.joint)].insert(taken[at(slider.joint)].end(), {u, -u});
  }
  std::vector<Point> places;
  for (std::size_t j = 0; j < now.size(); ++j) {
    const Point best = clearest_direction(taken[j]);
    const bool slider = std::any_of(d.sliders.begin(), d.sliders.end(), [&](const auto& s) { return at(s.joint) == j; });
    places.push_back(now[j] + best * (slider ? 6.5 : 4.5) * scene.unit);
  }
  return places;
}

constexpr double name_size = 4.5;  // font size of the joints' names, in units

// Each joint's name, centred at its place.
std::string joint_names(const Scene& scene, const std::vector<Point>& places) {
  const auto& joints = scene.model.description().joints;
  std::string svg;
  for (std::size_t j = 0; j < places.size(); ++j) {
    svg += fmt::format("<text x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"{:.3g}\" fill=\"#222\" text-anchor=\"middle\" "
                       "dominant-baseline=\"central\">{}</text>\n",
                       places[j].x(), -places[j].y(), name_size * scene.unit, xml_escaped(joints[j].name));
  }
  return svg;
}

// The frame grown to hold every name (about 0.6 em per character, centred).
void include_names(Frame& frame, const Scene& scene, const std::vector<Point>& places) {
  const double em = name_size * scene.unit;
  const auto& joints = scene.model.description().joints;
  for (std::size_t j = 0; j < places.size(); ++j) {
    const Point half(0.3 * em * static_cast<double>(joints[j].name.size()), 0.5 * em);
    include(frame, places[j] - half);
    include(frame, places[j] + half);
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

std::string paths_caption(const Scene& scene, const std::string& longest) {
  return fmt::format("dashed: the joints' paths over {} assembled poses; heavier: {}'s, the longest{}", scene.frames.size(),
                     longest, scene.model.crank_driven() ? " but the crank pin's" : "");
}

// Each moving joint's velocity as an arrow from the joint, the longest arrow_share of the frame's
// larger side; the frame grows to hold the tips and the caption states the scale. A velocity that is
// missing or not finite (a singular J) is said so, not drawn.
std::string arrows_at(const Scene& scene, const JointPositions& now, const Eigen::VectorXd& v, Frame& frame,
                      Caption& caption) {
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
    svg += fmt::format("<line class=\"velocity\" x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" "
                       "stroke-width=\"{:.3g}\" marker-end=\"url(#velocity-head)\"/>\n",
                       from.x(), -from.y(), to.x(), -to.y(), arrow_colour, 0.7 * scene.unit);
  }
  caption.lines.push_back(fmt::format("arrows: velocity per {}; an arrow 1 unit long stands for {:.3g} units per {}",
                                      model.crank_driven() ? "radian of crank" : "unit of slider travel", 1.0 / scale,
                                      model.crank_driven() ? "radian" : "unit of travel"));
  return svg;
}

}  // namespace

std::string linkage_pose_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                             std::size_t pose, bool velocity_arrows) {
  if (pose >= sweep.poses.size()) throw std::invalid_argument(fmt::format("no pose {} in the sweep", pose));
  if (!assembled(model, sweep.poses[pose])) {
    throw std::invalid_argument(fmt::format("the pose at {} did not assemble", driver_text(model, sweep.poses[pose].driver)));
  }
  const Scene scene = scene_of(model, sweep);
  const std::size_t first = static_cast<std::size_t>(
      std::find(scene.sweep_index.begin(), scene.sweep_index.end(), pose) - scene.sweep_index.begin());
  const JointPositions& now = scene.frames[first];
  std::vector<Point> points;
  for (const auto& joints : scene.frames) points.insert(points.end(), joints.begin(), joints.end());
  Frame frame = frame_of(points);

  std::string longest;
  Caption caption{{fmt::format("{} at {}", title_of(model), driver_text(model, sweep.poses[pose].driver))}, scene.unit};
  std::string drawing = joint_paths(scene, longest);
  caption.lines.push_back(paths_caption(scene, longest));
  if (scene.skipped > 0) caption.lines.push_back(skipped_line(scene, sweep));

  const Eigen::VectorXd& velocity = sweep.poses[pose].velocity;
  const std::string arrows = velocity_arrows ? arrows_at(scene, now, velocity, frame, caption) : std::string();
  const std::vector<Point> places = label_places(scene, now, velocity);
  include_names(frame, scene, places);
  frame = caption.fitted(frame);
  drawing = guides_across(scene, frame) + drawing + linkage(scene, first, 0.0);
  // The arrows over everything (a joint's circle would hide an arrow's tail), then the names.
  drawing += arrows + joint_names(scene, places);
  return picture(scene, frame, caption, drawing);
}

std::string linkage_animation_svg(const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                                  double seconds) {
  const Scene scene = scene_of(model, sweep);
  std::vector<Point> points;
  for (const auto& joints : scene.frames) points.insert(points.end(), joints.begin(), joints.end());
  Frame frame = frame_of(points);
  const auto& first = sweep.poses[scene.sweep_index.front()], &last = sweep.poses[scene.sweep_index.back()];
  Caption caption{{fmt::format("{}, {} poses from {} to {}", title_of(model), scene.frames.size(),
                               driver_text(model, first.driver), model.crank_driven() ? fmt::format("{:g} deg", last.driver)
                                                                                      : fmt::format("{:g}", last.driver))},
                  scene.unit};
  std::string longest;
  std::string drawing = joint_paths(scene, longest);
  caption.lines.push_back(paths_caption(scene, longest));
  caption.lines.push_back(scene.skipped > 0 ? skipped_line(scene, sweep) : std::string("every pose of the sweep assembled"));
  frame = caption.fitted(frame);
  drawing = guides_across(scene, frame) + drawing + linkage(scene, 0, seconds);
  return picture(scene, frame, caption, drawing);
}

}  // namespace numlab::cli
