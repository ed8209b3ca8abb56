#include "scenes/mustang_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "output/svg_canvas.hpp"

namespace numlab::cli {

namespace {

using mechanisms::MustangJoints;
using Point = Eigen::Vector2d;
constexpr double scale = 0.1;  // the linkage is about 10 units across (the Jansen leg about 100)

struct Bar {
  int from, to;
  const char* colour;
  double width;
};
// Major links heavy (seed 003: LineWidth 8), minor links and the ground thin (LineWidth 1).
constexpr Bar bars[] = {
    {0, 1, "#999", 0.5},     {1, 2, "#999", 0.5},                                                  // ground
    {0, 5, "#222", 0.6},     {1, 3, "#222", 0.6},     {3, 4, "#222", 0.6},                         // minor links
    {7, 10, "#222", 0.6},    {10, 8, "#222", 0.6},    {10, 11, "#222", 0.6},
    {2, 4, "#c0392b", 2.2},  {4, 6, "#c0392b", 2.2},  {6, 7, "#c0392b", 2.2},                      // major link 1
    {5, 6, "#c2185b", 2.2},  {6, 8, "#c2185b", 2.2},  {8, 9, "#c2185b", 2.2},                      // major link 2
    {9, 11, "#00acc1", 2.2}, {11, 12, "#00acc1", 2.2}};                                             // major link 3

std::vector<MustangJoints> frames_of(const mechanisms::MustangSweep& sweep) {
  if (sweep.poses.empty()) throw std::invalid_argument("no poses to draw");
  std::vector<MustangJoints> frames;
  for (const auto& pose : sweep.poses) frames.push_back(pose.joints);
  return frames;
}

// Every joint of every frame, widened about its middle to at least 0.9 times its height (room
// for the caption).
Frame frame_for(const std::vector<MustangJoints>& frames) {
  std::vector<Point> points;
  for (const auto& joints : frames) points.insert(points.end(), joints.begin(), joints.end());
  Frame frame = frame_of(points);
  const double missing = 0.9 * (frame.max_y - frame.min_y) - (frame.max_x - frame.min_x);
  if (missing > 0.0) {
    frame.min_x -= missing / 2;
    frame.max_x += missing / 2;
  }
  return frame;
}

std::string tip_path(const std::vector<MustangJoints>& frames) {
  std::string points;
  for (const auto& joints : frames) points += xy(joints[12]) + " ";
  return fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"#2471a3\" stroke-width=\"{:.3f}\" "
                     "stroke-dasharray=\"{:.3f} {:.3f}\"/>\n",
                     points, 0.8 * scale, 2 * scale, 1.5 * scale);
}

// The linkage at frames[0]; with seconds > 0, every frame in turn.
std::string linkage(const std::vector<MustangJoints>& frames, double seconds, bool labels) {
  const MustangJoints& now = frames[0];
  auto animate = [&](const char* attribute, int joint, bool x) {
    if (seconds <= 0.0) return std::string();
    std::string values;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      values += fmt::format("{:.4f};", x ? frames[k][joint].x() : -frames[k][joint].y());
    }
    values.pop_back();
    return fmt::format("<animate attributeName=\"{}\" dur=\"{:.3f}s\" repeatCount=\"indefinite\" values=\"{}\"/>",
                       attribute, seconds, values);
  };
  std::string svg;
  for (int j = 0; j < 3; ++j) svg += fixed_pivot(now[j], 0.35 * scale);  // under the links
  for (const Bar& bar : bars) {
    svg += fmt::format("<line x1=\"{:.4f}\" y1=\"{:.4f}\" x2=\"{:.4f}\" y2=\"{:.4f}\" stroke=\"{}\" stroke-width=\"{:.3f}\" "
                       "stroke-linecap=\"round\">{}{}{}{}</line>\n",
                       now[bar.from].x(), -now[bar.from].y(), now[bar.to].x(), -now[bar.to].y(), bar.colour,
                       bar.width * scale, animate("x1", bar.from, true), animate("y1", bar.from, false),
                       animate("x2", bar.to, true), animate("y2", bar.to, false));
  }
  for (int j = 0; j < mechanisms::mustang_joint_count; ++j) {
    svg += fmt::format("<circle cx=\"{:.4f}\" cy=\"{:.4f}\" r=\"{:.3f}\" fill=\"white\" stroke=\"#222\" "
                       "stroke-width=\"{:.3f}\">{}{}</circle>\n",
                       now[j].x(), -now[j].y(), 1.2 * scale, 0.5 * scale, animate("cx", j, true), animate("cy", j, false));
    if (labels) {
      svg += fmt::format("<text x=\"{:.3f}\" y=\"{:.3f}\" font-size=\"{:.3f}\" fill=\"#222\">{}</text>\n",
                         now[j].x() + 1.8 * scale, -now[j].y() - 1.8 * scale, 4.0 * scale,
                         mechanisms::mustang_joint_names[static_cast<std::size_t>(j)]);
    }
  }
  return svg;
}

// "assembles from -41.42 deg (loop 2 stops it) to 56.45 deg (loop 3 stops it)", as far as known.
std::string limits_text(const mechanisms::MustangSweep& sweep) {
  auto end = [](const mechanisms::MustangLimit& limit) {
    return limit.reached && limit.status == Status::cannot_assemble
               ? fmt::format("{:.2f} deg (loop {} stops it)", limit.last_assembled_deg, limit.loop)
               : std::string("?");
  };
  if (!sweep.lower.reached && !sweep.upper.reached) return "the sweep stayed inside the assembly range";
  return "assembles from " + end(sweep.lower) + " to " + end(sweep.upper);
}

// The header, sized to fit 800 x 650 pixels, and two caption lines above the drawing.
std::string header(const Frame& frame, const std::string& title, const std::string& subtitle) {
  const double width = frame.max_x - frame.min_x + 24.0 * scale, height = frame.max_y - frame.min_y + 32.0 * scale;
  return frame.header(std::min(800.0, 650.0 * width / height), scale) +
         fmt::format("<text x=\"{0:.2f}\" y=\"{1:.2f}\" font-size=\"{2:.2f}\" fill=\"#333\">{3}"
                     "<tspan x=\"{0:.2f}\" dy=\"{4:.2f}\" font-size=\"{5:.2f}\">dashed: the path of the roof tip P12; "
                     "heavy: the three bent major links</tspan>"
                     "<tspan x=\"{0:.2f}\" dy=\"{4:.2f}\" font-size=\"{5:.2f}\">{6}</tspan></text>\n",
                     frame.min_x, -frame.max_y - 15.0 * scale, 3.4 * scale, title, 3.6 * scale, 2.6 * scale, subtitle);
}

}  // namespace

std::string mustang_pose_svg(const mechanisms::MustangSweep& sweep, std::size_t pose) {
  auto frames = frames_of(sweep);
  const Frame frame = frame_for(frames);
  std::string svg = header(frame, fmt::format("Mustang roof linkage at theta = {:g} deg", sweep.poses[pose].crank_deg),
                           limits_text(sweep));
  svg += tip_path(frames);
  std::swap(frames[0], frames[pose]);
  return svg + linkage({frames[0]}, 0.0, true) + "</svg>\n";
}

std::string mustang_animation_svg(const mechanisms::MustangSweep& sweep, double seconds) {
  auto frames = frames_of(sweep);
  const Frame frame = frame_for(frames);
  // Forth and back, as seed 003's movie played.
  for (std::size_t k = frames.size(); k-- > 1;) frames.push_back(frames[k - 1]);
  std::string svg = header(frame, fmt::format("Mustang roof linkage, {} poses from {:g} to {:g} deg and back",
                                               sweep.poses.size(), sweep.poses.front().crank_deg, sweep.poses.back().crank_deg),
                           limits_text(sweep));
  svg += tip_path(frames_of(sweep));
  return svg + linkage(frames, seconds, false) + "</svg>\n";
}

}  // namespace numlab::cli
