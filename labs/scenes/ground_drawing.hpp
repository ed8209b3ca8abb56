#pragma once
// The ground as textbooks draw it: each ground pivot's triangle, standing on a hatched strip; pivots
// at one height share one strip, from the leftmost to the rightmost (the ground between them), and a
// pivot at a height of its own gets a short strip under it.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scenes/label_placement.hpp"

namespace numlab::cli {

// One hatched strip: its top edge at height `y` from `left` to `right` (scene coordinates, y up).
struct GroundStrip {
  double left = 0.0, right = 0.0, y = 0.0;
  std::vector<int> pivots;  // indices into the pivots it carries
};

// The strips under `pivots` (scene coordinates), sizes in `unit`: pivots whose triangles' bases lie
// within half a unit of one height share a strip reaching 5 units past the outer ones.
std::vector<GroundStrip> ground_strips(const std::vector<Eigen::Vector2d>& pivots, double unit);

// The triangles and the strips as SVG (y flipped), class "ground".
std::string ground_svg(const std::vector<Eigen::Vector2d>& pivots, double unit);

// The boxes the ground takes (each triangle with its strip), for the label placement.
std::vector<LabelBox> ground_boxes(const std::vector<Eigen::Vector2d>& pivots, double unit);

}  // namespace numlab::cli
