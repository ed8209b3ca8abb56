#include "scenes/jansen_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "output/svg_canvas.hpp"

namespace numlab::cli {

namespace {

using mechanisms::JansenJoint;
using mechanisms::JansenJoints;
using Point = Eigen::Vector2d;

// The bars drawn (links and the rigid triangles' sides), by joint.
constexpr std::pair<JansenJoint, JansenJoint> bars[] = {
    {JansenJoint::O, JansenJoint::A},  {JansenJoint::A, JansenJoint::B},  {JansenJoint::P1, JansenJoint::B},
    {JansenJoint::B, JansenJoint::C},  {JansenJoint::P1, JansenJoint::C}, {JansenJoint::C, JansenJoint::E},
    {JansenJoint::A, JansenJoint::D},  {JansenJoint::P1, JansenJoint::D}, {JansenJoint::D, JansenJoint::E},
    {JansenJoint::D, JansenJoint::F},  {JansenJoint::E, JansenJoint::F}};


std::string foot_path(const std::vector<Point>& feet, const std::string& colour) {
  std::string points;
  for (const Point& p : feet) points += xy(p) + " ";
  return fmt::format("<polygon points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"0.8\" stroke-dasharray=\"2 1.5\"/>\n",
                     points, colour);
}

// One leg's bars and joints at `joints`; with `frames` (one JansenJoints per time step) they move.
std::string leg(const std::vector<JansenJoints>& frames, std::size_t first, const std::string& colour,
                double seconds, bool labels) {
  const JansenJoints& now = frames[first];
  const bool animated = seconds > 0.0;
  auto values = [&](JansenJoint joint, bool x) {
    std::string list;
    for (std::size_t k = 0; k <= frames.size(); ++k) {
      const Point& p = frames[(first + k) % frames.size()][at(joint)];
      list += fmt::format("{:.3f};", x ? p.x() : -p.y());
    }
    list.pop_back();
    return list;
  };
  auto animate = [&](const char* attribute, JansenJoint joint, bool x) {
    if (!animated) return std::string();
    return fmt::format("<animate attributeName=\"{}\" dur=\"{:.3f}s\" repeatCount=\"indefinite\" values=\"{}\"/>",
                       attribute, seconds, values(joint, x));
  };
  std::string svg;
  for (const auto& [from, to] : bars) {
    const bool heavy = from == JansenJoint::O;  // the crank
    svg += fmt::format("<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"{}\" stroke-width=\"{}\" "
                       "stroke-linecap=\"round\">{}{}{}{}</line>\n",
                       now[at(from)].x(), -now[at(from)].y(), now[at(to)].x(), -now[at(to)].y(),
                       heavy ? "#c0392b" : colour, heavy ? 3.0 : 2.0, animate("x1", from, true),
                       animate("y1", from, false), animate("x2", to, true), animate("y2", to, false));
  }
  for (std::size_t j = 0; j < now.size(); ++j) {
    const auto joint = static_cast<JansenJoint>(j);
    svg += fmt::format("<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"1.8\" fill=\"white\" stroke=\"#222\" stroke-width=\"0.8\">{}{}</circle>\n",
                       now[j].x(), -now[j].y(), animate("cx", joint, true), animate("cy", joint, false));
    if (labels && !animated) {
      svg += fmt::format("<text x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"5\" fill=\"#222\">{}</text>\n", now[j].x() + 2.5,
                         -now[j].y() - 2.5, mechanisms::jansen_joint_names[j]);
    }
  }
  return svg;
}

std::vector<JansenJoints> frames_of(const mechanisms::JansenSweep& sweep) {
  if (sweep.poses.empty()) throw std::invalid_argument("no poses to draw");
  std::vector<JansenJoints> frames;
  for (const auto& pose : sweep.poses) frames.push_back(pose.joints);
  return frames;
}

std::vector<Point> all_points(const std::vector<JansenJoints>& frames) {
  std::vector<Point> points;
  for (const auto& joints : frames) points.insert(points.end(), joints.begin(), joints.end());
  return points;
}

std::vector<Point> feet(const std::vector<JansenJoints>& frames) {
  std::vector<Point> path;
  for (const auto& joints : frames) path.push_back(joints[at(JansenJoint::F)]);
  return path;
}

}  // namespace

std::string jansen_pose_svg(const mechanisms::JansenSweep& sweep, std::size_t pose) {
  const auto frames = frames_of(sweep);
  const Frame frame = frame_of(all_points(frames));
  std::string svg = frame.header(700);
  svg += caption(frame, fmt::format("Jansen leg at crank {:g} deg; dashed: the path of the foot F", sweep.poses[pose].crank_deg));
  svg += fmt::format("<circle cx=\"0\" cy=\"0\" r=\"15\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"0.5\" stroke-dasharray=\"1 1\"/>\n");
  svg += foot_path(feet(frames), "#2471a3");
  svg += fixed_pivot(frames[0][at(JansenJoint::O)]) + fixed_pivot(frames[0][at(JansenJoint::P1)]);
  svg += leg(frames, pose, "#34495e", 0.0, true);
  return svg + "</svg>\n";
}

std::string jansen_animation_svg(const mechanisms::JansenSweep& sweep, double seconds) {
  const auto frames = frames_of(sweep);
  const Frame frame = frame_of(all_points(frames));
  std::string svg = frame.header(700);
  svg += caption(frame, fmt::format("Jansen leg, {} poses from {:g} to {:g} deg", frames.size(),
                                    sweep.poses.front().crank_deg, sweep.poses.back().crank_deg));
  svg += foot_path(feet(frames), "#2471a3");
  svg += fixed_pivot(frames[0][at(JansenJoint::O)]) + fixed_pivot(frames[0][at(JansenJoint::P1)]);
  svg += leg(frames, 0, "#34495e", seconds, false);
  return svg + "</svg>\n";
}

std::string beest_svg(const mechanisms::JansenSweep& sweep, double seconds) {
  const auto cycle = frames_of(sweep);
  if (cycle.size() % 2 != 0) throw std::invalid_argument("the beest needs a cycle with an even number of poses");
  // The hind pair: each joint mirrored about the vertical through O, then moved back by the body.
  const double body = 170.0;
  std::vector<JansenJoints> hind = cycle;
  for (auto& joints : hind) {
    for (Point& p : joints) p = Point(-p.x() - body, p.y());
  }
  const std::size_t half_turn = cycle.size() / 2;
  std::vector<Point> points = all_points(cycle);
  const std::vector<Point> hind_points = all_points(hind);
  points.insert(points.end(), hind_points.begin(), hind_points.end());
  const Frame frame = frame_of(points);
  std::string svg = frame.header(900);
  svg += caption(frame, fmt::format("Seed 000's beest: one solved cycle of {} poses, legs half a turn apart, hind pair "
                                    "mirrored", cycle.size()));
  svg += fmt::format("<line x1=\"{:.2f}\" y1=\"0\" x2=\"0\" y2=\"0\" stroke=\"#7f8c8d\" stroke-width=\"4\"/>\n", -body);
  // Back legs first (lighter), then the front ones.
  svg += leg(cycle, half_turn, "#95a5a6", seconds, false);
  svg += leg(hind, 0, "#95a5a6", seconds, false);
  svg += leg(cycle, 0, "#2c3e50", seconds, false);
  svg += leg(hind, half_turn, "#2c3e50", seconds, false);
  return svg + "</svg>\n";
}

}  // namespace numlab::cli
