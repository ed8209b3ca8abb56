#pragma once
// Where the joints' names go in a scene: apart from each other and off the bars. A simple,
// deterministic placement, one name after the other:
//
//  1. candidates: 16 directions around the joint, each at three distances from its circle
//     (nearest first);
//  2. a candidate's clearance: the smallest gap between its box and anything drawn (the names
//     already placed, the joints' circles, the bars with their width, the ground's boxes), a path
//     counting less (its gap plus a bonus: a name over a dashed path still reads);
//  3. the candidate with the largest clearance, capped at `enough` so that among the clear ones the
//     nearest, and then the first direction, wins;
//  4. a second pass places each name again with all the others where the first pass put them.
//
// Coordinates are the scene's (y up); boxes are axis-aligned, a name's box its text's extent.

#include <Eigen/Core>
#include <vector>

namespace numlab::cli {

struct LabelBox {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d half = Eigen::Vector2d::Zero();  // half the width and half the height
};

// The gap between two boxes (0 when they touch or overlap).
double box_gap(const LabelBox& a, const LabelBox& b);
// True when two boxes share more than a boundary.
bool boxes_overlap(const LabelBox& a, const LabelBox& b);
// The distance from a box to a segment (0 when they meet).
double box_segment_distance(const LabelBox& box, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// What a name must keep clear of.
struct LabelObstacles {
  struct Segment {
    Eigen::Vector2d a, b;
    double half_width = 0.0;
    bool soft = false;  // a path: its gap counts with a bonus
  };
  struct Disc {
    Eigen::Vector2d centre;
    double radius = 0.0;
  };
  std::vector<Segment> segments;
  std::vector<Disc> discs;
  std::vector<LabelBox> boxes;
};

// One box per anchor (a joint at `anchors[k]`, its circle `radius`, its name's half extent
// `halves[k]`), placed by steps 1-4 above; `unit` is the scene's size unit.
std::vector<LabelBox> place_labels(const std::vector<Eigen::Vector2d>& anchors, const std::vector<Eigen::Vector2d>& halves,
                                   double radius, const LabelObstacles& obstacles, double unit);

}  // namespace numlab::cli
