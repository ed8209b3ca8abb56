#include "scenes/ground_drawing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "output/svg_canvas.hpp"

namespace numlab::cli {

namespace {
constexpr double triangle_height = 6.0, overhang = 5.0, hatch_depth = 2.0;  // in units
}  // namespace

std::vector<GroundStrip> ground_strips(const std::vector<Eigen::Vector2d>& pivots, double unit) {
  // 1. The pivots by the height of their triangles' bases, lowest first (then left to right).
  std::vector<int> order(pivots.size());
  std::iota(order.begin(), order.end(), 0);
  auto at = [&](int k) { return pivots[static_cast<std::size_t>(k)]; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return at(a).y() < at(b).y() || (at(a).y() == at(b).y() && at(a).x() < at(b).x());
  });
  // 2. A run of pivots within half a unit of the first one's height shares a strip.
  std::vector<GroundStrip> strips;
  for (const int k : order) {
    const double base = at(k).y() - triangle_height * unit;
    if (strips.empty() || base - strips.back().y > 0.5 * unit) {
      strips.push_back({at(k).x() - overhang * unit, at(k).x() + overhang * unit, base, {k}});
      continue;
    }
    GroundStrip& strip = strips.back();
    strip.left = std::min(strip.left, at(k).x() - overhang * unit);
    strip.right = std::max(strip.right, at(k).x() + overhang * unit);
    strip.pivots.push_back(k);
  }
  return strips;
}

std::string ground_svg(const std::vector<Eigen::Vector2d>& pivots, double unit) {
  std::string svg;
  for (const GroundStrip& strip : ground_strips(pivots, unit)) {
    // The strip's top edge, then hatches every 2 units slanting down to the left.
    const double y = -strip.y;
    std::string d = fmt::format("M {:.3f} {:.3f} H {:.3f}", strip.left, y, strip.right);
    const int hatches = std::max(1, static_cast<int>(std::floor((strip.right - strip.left) / (2.0 * unit))));
    for (int k = 0; k < hatches; ++k) {
      d += fmt::format(" M {:.3f} {:.3f} l {:.3f} {:.3f}", strip.left + (2.0 * k + 1.5) * unit, y, -1.5 * unit, hatch_depth * unit);
    }
    svg += fmt::format("<path class=\"ground\" d=\"{}\" stroke=\"#666\" stroke-width=\"{:.3g}\" fill=\"none\"/>\n", d, 0.4 * unit);
  }
  for (const Eigen::Vector2d& p : pivots) svg += fixed_pivot(p, unit);
  return svg;
}

std::vector<LabelBox> ground_boxes(const std::vector<Eigen::Vector2d>& pivots, double unit) {
  std::vector<LabelBox> boxes;
  for (const GroundStrip& strip : ground_strips(pivots, unit)) {
    boxes.push_back({{(strip.left + strip.right) / 2.0, strip.y - hatch_depth * unit / 2.0},
                     {(strip.right - strip.left) / 2.0, hatch_depth * unit / 2.0}});
  }
  for (const Eigen::Vector2d& p : pivots) {
    boxes.push_back({{p.x(), p.y() - triangle_height * unit / 2.0}, {3.5 * unit, triangle_height * unit / 2.0}});
  }
  return boxes;
}

}  // namespace numlab::cli
