#pragma once
// Layout for SVG scenes beyond svg_canvas.hpp: a body's outline, the clearest side of a point for its
// name, a line clipped to a frame, and caption lines that the frame grows to hold.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "output/svg_canvas.hpp"

namespace numlab::cli {

// A body's outline: the convex hull of its local coordinates, as joint indices in turning order.
// A rigid body that cannot flip keeps that order in every pose.
std::vector<int> body_outline(const mechanisms::BodySpec& body);

// A body whose local points all lie on one line (within 1e-9 of its size, the largest distance
// between two of its points: the reader's test) is drawn as a bar. True for such a body, with its
// two outer joints (the two local points farthest apart) in `first` and `second`.
bool body_on_one_line(const mechanisms::BodySpec& body, int& first, int& second);

// Of sixteen directions, the one farthest in angle from every unit vector in `taken`.
Eigen::Vector2d clearest_direction(const std::vector<Eigen::Vector2d>& taken);

// The part of the line through `through` along `direction` inside `box`; false when it misses.
bool line_across(const Frame& box, const Eigen::Vector2d& through, const Eigen::Vector2d& direction, Eigen::Vector2d& from,
                 Eigen::Vector2d& to);

void include(Frame& frame, const Eigen::Vector2d& p);
double larger_side(const Frame& frame);

// &, <, > and " as XML entities.
std::string xml_escaped(const std::string& text);

// Caption lines above a drawing: a title, then smaller lines; sizes in units of `unit`.
struct Caption {
  std::vector<std::string> lines;
  double unit = 1.0;
  // The frame grown until the caption fits above it: wider to the right, and taller than
  // Frame::header's room at the top (20 units: a title and three lines) when there are more lines.
  Frame fitted(Frame frame) const;
  // The <text> element, placed in that room.
  std::string svg(const Frame& fitted_frame) const;
};

}  // namespace numlab::cli
