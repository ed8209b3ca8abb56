#include "scenes/label_placement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace numlab::cli {

namespace {

using Point = Eigen::Vector2d;

double point_box_distance(const Point& p, const LabelBox& box) {
  const double dx = std::max(std::abs(p.x() - box.centre.x()) - box.half.x(), 0.0);
  const double dy = std::max(std::abs(p.y() - box.centre.y()) - box.half.y(), 0.0);
  return std::hypot(dx, dy);
}

double point_segment_distance(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// Whether the segment a-b passes through the box (Liang-Barsky clipping to t in [0, 1]).
bool segment_meets_box(const LabelBox& box, const Point& a, const Point& b) {
  double first = 0.0, last = 1.0;
  const Point d = b - a;
  for (int i = 0; i < 2; ++i) {
    const double low = box.centre[i] - box.half[i], high = box.centre[i] + box.half[i];
    if (d[i] == 0.0) {
      if (a[i] < low || a[i] > high) return false;
      continue;
    }
    const double t0 = (low - a[i]) / d[i], t1 = (high - a[i]) / d[i];
    first = std::max(first, std::min(t0, t1));
    last = std::min(last, std::max(t0, t1));
  }
  return first <= last;
}

// The 16 directions, those farthest in angle from the bars that leave the anchor first (stable).
std::vector<Point> directions_around(const Point& anchor, const LabelObstacles& obstacles, double unit) {
  std::vector<Point> taken;
  for (const auto& s : obstacles.segments) {
    if (s.soft) continue;
    if ((s.a - anchor).norm() <= 1e-6 * unit && (s.b - s.a).norm() > 0.0) taken.push_back((s.b - s.a).normalized());
    if ((s.b - anchor).norm() <= 1e-6 * unit && (s.a - s.b).norm() > 0.0) taken.push_back((s.a - s.b).normalized());
  }
  std::vector<std::pair<double, Point>> scored;
  for (int c = 0; c < 16; ++c) {
    const double angle = std::numbers::pi / 4.0 + 2.0 * std::numbers::pi * c / 16.0;  // from up-right
    const Point direction(std::cos(angle), std::sin(angle));
    double nearest = 2.0;  // 1 - cos of the smallest angle to a bar
    for (const Point& t : taken) nearest = std::min(nearest, 1.0 - direction.dot(t));
    scored.emplace_back(nearest, direction);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first + 1e-12; });
  std::vector<Point> directions;
  for (const auto& entry : scored) directions.push_back(entry.second);
  return directions;
}

}  // namespace

double box_gap(const LabelBox& a, const LabelBox& b) {
  const double dx = std::max(std::abs(a.centre.x() - b.centre.x()) - a.half.x() - b.half.x(), 0.0);
  const double dy = std::max(std::abs(a.centre.y() - b.centre.y()) - a.half.y() - b.half.y(), 0.0);
  return std::hypot(dx, dy);
}

bool boxes_overlap(const LabelBox& a, const LabelBox& b) {
  return std::abs(a.centre.x() - b.centre.x()) < a.half.x() + b.half.x() &&
         std::abs(a.centre.y() - b.centre.y()) < a.half.y() + b.half.y();
}

double box_segment_distance(const LabelBox& box, const Point& a, const Point& b) {
  if (segment_meets_box(box, a, b)) return 0.0;
  double distance = std::min(point_box_distance(a, box), point_box_distance(b, box));
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      const Point corner = box.centre + Point(sx * box.half.x(), sy * box.half.y());
      distance = std::min(distance, point_segment_distance(corner, a, b));
    }
  }
  return distance;
}

std::vector<LabelBox> place_labels(const std::vector<Point>& anchors, const std::vector<Point>& halves, double radius,
                                   const LabelObstacles& obstacles, double unit) {
  const double enough = 2.0 * unit, path_bonus = 2.0 * unit;
  const std::array<double, 4> gaps = {0.8 * unit, 3.0 * unit, 6.0 * unit, 10.0 * unit};
  std::vector<LabelBox> boxes(anchors.size());
  std::vector<bool> placed(anchors.size(), false);

  // 2. The clearance of `box` for name k: its smallest gap to anything drawn, capped.
  auto clearance = [&](std::size_t k, const LabelBox& box) {
    double gap = enough;
    for (std::size_t other = 0; other < boxes.size(); ++other) {
      if (other != k && placed[other]) gap = std::min(gap, box_gap(box, boxes[other]));
    }
    for (const auto& disc : obstacles.discs) gap = std::min(gap, point_box_distance(disc.centre, box) - disc.radius);
    for (const auto& b : obstacles.boxes) gap = std::min(gap, box_gap(box, b));
    for (const auto& s : obstacles.segments) {
      const double reach = s.half_width + (s.soft ? -path_bonus : 0.0);
      // A cheap test first: a segment whose bounding box is far cannot lower the gap.
      const Point low = s.a.cwiseMin(s.b), high = s.a.cwiseMax(s.b);
      const LabelBox around{(low + high) / 2.0, (high - low) / 2.0};
      if (box_gap(box, around) - reach >= gap) continue;
      gap = std::min(gap, box_segment_distance(box, s.a, s.b) - reach);
    }
    return gap;
  };
  // 1 and 3. The best of the candidates around anchor k: nearest ring first, then the directions.
  auto place = [&](std::size_t k) {
    const std::vector<Point> directions = directions_around(anchors[k], obstacles, unit);
    double best = -std::numeric_limits<double>::infinity();
    for (const double gap : gaps) {
      for (const Point& d : directions) {
        const double along_x = std::abs(d.x()) > 1e-12 ? halves[k].x() / std::abs(d.x()) : std::numeric_limits<double>::infinity();
        const double along_y = std::abs(d.y()) > 1e-12 ? halves[k].y() / std::abs(d.y()) : std::numeric_limits<double>::infinity();
        const LabelBox box{anchors[k] + d * (radius + gap + std::min(along_x, along_y)), halves[k]};
        const double score = clearance(k, box);
        if (score > best + 1e-12 * unit) best = score, boxes[k] = box;
        if (best >= enough) return;
      }
    }
  };
  for (std::size_t k = 0; k < anchors.size(); ++k) place(k), placed[k] = true;
  // 4. Again, each against all the others.
  for (std::size_t k = 0; k < anchors.size(); ++k) place(k);
  return boxes;
}

}  // namespace numlab::cli
