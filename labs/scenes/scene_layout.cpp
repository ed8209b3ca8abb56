#include "scenes/scene_layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace numlab::cli {

namespace {
using Point = Eigen::Vector2d;
constexpr double title_size = 4.5, line_size = 2.9, line_gap = 3.8;
}  // namespace

std::vector<int> body_outline(const mechanisms::BodySpec& body) {
  // Andrew's monotone chain on the local coordinates.
  std::vector<std::size_t> order(body.joints.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  const auto& p = body.local;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return p[a].x() < p[b].x() || (p[a].x() == p[b].x() && p[a].y() < p[b].y());
  });
  auto turn = [&](std::size_t o, std::size_t a, std::size_t b) {
    const Point u = p[a] - p[o], v = p[b] - p[o];
    return u.x() * v.y() - u.y() * v.x();
  };
  std::vector<std::size_t> hull;
  for (int pass = 0; pass < 2; ++pass) {  // lower hull left to right, then upper hull right to left
    const std::size_t base = hull.size();
    for (const std::size_t k : order) {
      while (hull.size() >= base + 2 && turn(hull[hull.size() - 2], hull.back(), k) <= 0.0) hull.pop_back();
      hull.push_back(k);
    }
    hull.pop_back();  // the last point starts the other pass
    std::reverse(order.begin(), order.end());
  }
  std::vector<int> joints;
  for (const std::size_t k : hull) joints.push_back(body.joints[k]);
  return joints;
}

bool body_on_one_line(const mechanisms::BodySpec& body, int& first, int& second) {
  // 1. The two local points farthest apart: the body's size.
  const auto& p = body.local;
  std::size_t a = 0, b = 0;
  double size = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if ((p[j] - p[i]).norm() > size) size = (p[j] - p[i]).norm(), a = i, b = j;
    }
  }
  if (size == 0.0 || body.joints.size() != p.size()) return false;
  // 2. Every point within 1e-9 of the size from the line through them.
  const Point u = (p[b] - p[a]) / size;
  for (const Point& q : p) {
    const Point d = q - p[a];
    if (std::abs(u.x() * d.y() - u.y() * d.x()) > 1e-9 * size) return false;
  }
  first = body.joints[a];
  second = body.joints[b];
  return true;
}

Point clearest_direction(const std::vector<Point>& taken) {
  Point best(1.0, 0.0);
  double clearance = -1.0;
  for (int c = 0; c < 16; ++c) {
    const double angle = 2.0 * std::numbers::pi * c / 16.0;
    const Point direction(std::cos(angle), std::sin(angle));
    double nearest = 2.0;  // 1 - cos of the smallest angle to anything taken
    for (const Point& t : taken) nearest = std::min(nearest, 1.0 - direction.dot(t));
    if (nearest > clearance + 1e-12) clearance = nearest, best = direction;
  }
  return best;
}

bool line_across(const Frame& box, const Point& through, const Point& direction, Point& from, Point& to) {
  const Point low(box.min_x, box.min_y), high(box.max_x, box.max_y);
  double first = -std::numeric_limits<double>::infinity(), last = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i) {
    if (std::abs(direction[i]) > 1e-12) {
      const double a = (low[i] - through[i]) / direction[i], b = (high[i] - through[i]) / direction[i];
      first = std::max(first, std::min(a, b));
      last = std::min(last, std::max(a, b));
    } else if (through[i] < low[i] || through[i] > high[i]) {
      return false;  // parallel to this side and outside
    }
  }
  if (first > last) return false;
  from = through + first * direction;
  to = through + last * direction;
  return true;
}

void include(Frame& frame, const Point& p) {
  frame.min_x = std::min(frame.min_x, p.x());
  frame.max_x = std::max(frame.max_x, p.x());
  frame.min_y = std::min(frame.min_y, p.y());
  frame.max_y = std::max(frame.max_y, p.y());
}

double larger_side(const Frame& frame) { return std::max(frame.max_x - frame.min_x, frame.max_y - frame.min_y); }

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

Frame Caption::fitted(Frame frame) const {
  double widest = 0.0;  // ~0.52 em per character in Helvetica
  for (std::size_t k = 0; k < lines.size(); ++k) {
    widest = std::max(widest, 0.52 * (k == 0 ? title_size : line_size) * unit * static_cast<double>(lines[k].size()));
  }
  const double missing = widest - (frame.max_x - frame.min_x + 12.0 * unit);
  if (missing > 0.0) frame.max_x += missing;
  if (lines.size() > 4) frame.max_y += line_gap * unit * static_cast<double>(lines.size() - 4);
  return frame;
}

std::string Caption::svg(const Frame& frame) const {
  std::string text = fmt::format("<text x=\"{0:.3f}\" y=\"{1:.3f}\" font-size=\"{2:.3g}\" fill=\"#333\">{3}", frame.min_x,
                                 -frame.max_y - 15.0 * unit, title_size * unit, lines.empty() ? "" : lines[0]);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    text += fmt::format("<tspan x=\"{:.3f}\" dy=\"{:.3g}\" font-size=\"{:.3g}\">{}</tspan>", frame.min_x,
                        line_gap * unit, line_size * unit, lines[k]);
  }
  return text + "</text>\n";
}

}  // namespace numlab::cli
