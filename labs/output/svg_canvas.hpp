#pragma once
// What every SVG scene shares: a view box that holds the drawing (model y up, SVG y down), points,
// fixed pivots and a caption.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace numlab::cli {

// Model coordinates (y up) to SVG (y down), through a view box that holds every point.
struct Frame {
  double min_x, max_x, min_y, max_y;
  // The <svg> header and a white background; `scale` multiplies the margins (model units).
  std::string header(double pixel_width, double scale = 1.0) const;
};

Frame frame_of(const std::vector<Eigen::Vector2d>& points);

// "x,y" in SVG coordinates.
std::string xy(const Eigen::Vector2d& p);

// A fixed pivot: a small grey triangle under the point; `size` in model units.
std::string fixed_pivot(const Eigen::Vector2d& p, double size = 1.0);

// A line of text above the drawing.
std::string caption(const Frame& frame, const std::string& text, double scale = 1.0);

}  // namespace numlab::cli
