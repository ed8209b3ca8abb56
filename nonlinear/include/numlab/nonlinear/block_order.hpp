#pragma once
// The block lower-triangular order of a sparse system, derived from its Jacobian's pattern:
//
//   1. matching      - pair every equation with an unknown it contains (a perfect bipartite
//                      matching; none exists when the system is structurally singular);
//   2. dependencies  - unknown u depends on unknown v when v appears in the equation matched to u;
//   3. components    - the strongly connected components of that graph (Tarjan) are the blocks:
//                      unknowns that must be solved together;
//   4. order         - Tarjan finds the components sinks-first, which is exactly the order in which
//                      each block needs only unknowns solved before it.
//
// For seed 000's 8-equation Jansen model this recovers its four 2x2 blocks.

#include <Eigen/Core>
#include <vector>

#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

using SparsityPattern = Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>;

struct Block {
  std::vector<int> equations;  // rows of the system, 0-based
  std::vector<int> unknowns;   // columns of the system, 0-based; solved together
};

// Blocks in solving order. Throws std::invalid_argument when the pattern is not square or is
// structurally singular (no perfect matching), naming the first unmatched equation.
std::vector<Block> block_triangular_order(const SparsityPattern& pattern);

// The nonzero pattern of J at x, merged with J at a second, perturbed point so that an entry that
// happens to vanish at x (a cosine at pi/2, say) is not taken for a structural zero.
SparsityPattern jacobian_pattern(const DynamicSystem& system, const Eigen::VectorXd& x);

}  // namespace numlab::nonlinear
