#include "output/svg_canvas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace numlab::cli {

std::string Frame::header(double pixel_width, double scale) const {
  const double margin = 12.0 * scale, top = 20.0 * scale;  // the caption sits in the extra room at the top
  const double width = max_x - min_x + 2 * margin, height = max_y - min_y + margin + top;
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.2f} {:.2f} {:.2f} {:.2f}\" width=\"{:.0f}\" "
      "height=\"{:.0f}\" font-family=\"Helvetica, Arial, sans-serif\">\n"
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"white\"/>\n",
      min_x - margin, -max_y - top, width, height, pixel_width, pixel_width * height / width, min_x - margin,
      -max_y - top, width, height);
}

Frame frame_of(const std::vector<Eigen::Vector2d>& points) {
  Frame frame{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
              std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
  for (const Eigen::Vector2d& p : points) {
    frame.min_x = std::min(frame.min_x, p.x());
    frame.max_x = std::max(frame.max_x, p.x());
    frame.min_y = std::min(frame.min_y, p.y());
    frame.max_y = std::max(frame.max_y, p.y());
  }
  return frame;
}

std::string xy(const Eigen::Vector2d& p) { return fmt::format("{:.3f},{:.3f}", p.x(), -p.y()); }

std::string fixed_pivot(const Eigen::Vector2d& p, double size) {
  return fmt::format("<path d=\"M {:.3f} {:.3f} l {:.3f} {:.3f} l {:.3f} 0 z\" fill=\"#666\"/>\n", p.x(), -p.y(),
                     -3.5 * size, 6.0 * size, 7.0 * size);
}

std::string caption(const Frame& frame, const std::string& text, double scale) {
  return fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"{:.3g}\" fill=\"#333\">{}</text>\n", frame.min_x,
                     -frame.max_y - 10.0 * scale, 4.5 * scale, text);
}

}  // namespace numlab::cli
