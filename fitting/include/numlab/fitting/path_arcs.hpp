#pragma once
// A closed path (a foot's trace over one crank cycle) split into two arcs at its extreme x, so
// each arc can be fitted as y = p(x) (seed 001 eqs 22-23; the seed split by hand at fixed indices).

#include <Eigen/Core>

namespace numlab::fitting {

struct PathArc {
  Eigen::VectorXd x;  // increasing x
  Eigen::VectorXd y;
};

struct SplitPath {
  PathArc upper;  // the arc with the larger mean y
  PathArc lower;
  Eigen::Index min_x_index = 0;  // where the path was cut, as indices into the input
  Eigen::Index max_x_index = 0;
};

// The points in cyclic order from the leftmost point to the rightmost one form one arc, the rest
// (rightmost back to leftmost) the other; both arcs include the two cut points. Throws
// std::invalid_argument for fewer than 4 points, x and y of different sizes, or all x equal.
SplitPath split_at_extreme_x(const Eigen::VectorXd& x, const Eigen::VectorXd& y);

}  // namespace numlab::fitting
