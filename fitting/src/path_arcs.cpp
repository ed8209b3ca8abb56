#include "numlab/fitting/path_arcs.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace numlab::fitting {

namespace {

// Points first, first+1, ..., last (indices modulo n), sorted by x.
PathArc cyclic_arc(const Eigen::VectorXd& x, const Eigen::VectorXd& y, Eigen::Index first, Eigen::Index last) {
  const Eigen::Index n = x.size();
  std::vector<Eigen::Index> indices;
  for (Eigen::Index i = first;; i = (i + 1) % n) {
    indices.push_back(i);
    if (i == last) break;
  }
  std::sort(indices.begin(), indices.end(), [&](Eigen::Index a, Eigen::Index b) { return x(a) < x(b); });
  PathArc arc{Eigen::VectorXd(static_cast<Eigen::Index>(indices.size())),
              Eigen::VectorXd(static_cast<Eigen::Index>(indices.size()))};
  for (std::size_t k = 0; k < indices.size(); ++k) {
    arc.x(static_cast<Eigen::Index>(k)) = x(indices[k]);
    arc.y(static_cast<Eigen::Index>(k)) = y(indices[k]);
  }
  return arc;
}

}  // namespace

SplitPath split_at_extreme_x(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  if (x.size() != y.size()) throw std::invalid_argument("path: x and y have different sizes");
  if (x.size() < 4) throw std::invalid_argument("path: at least 4 points are needed to split it into two arcs");
  SplitPath split;
  // 1. The cut points: the leftmost and the rightmost point.
  x.minCoeff(&split.min_x_index);
  x.maxCoeff(&split.max_x_index);
  if (x(split.min_x_index) == x(split.max_x_index)) throw std::invalid_argument("path: every point has the same x");
  // 2. The two arcs between them, in cyclic order.
  PathArc forward = cyclic_arc(x, y, split.min_x_index, split.max_x_index);
  PathArc backward = cyclic_arc(x, y, split.max_x_index, split.min_x_index);
  // 3. The upper arc is the one with the larger mean height.
  if (forward.y.mean() >= backward.y.mean()) {
    split.upper = std::move(forward);
    split.lower = std::move(backward);
  } else {
    split.upper = std::move(backward);
    split.lower = std::move(forward);
  }
  return split;
}

}  // namespace numlab::fitting
