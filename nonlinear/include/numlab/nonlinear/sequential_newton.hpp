#pragma once
// Sequential (block-by-block) Newton: seed 000's four 2x2 blocks, seed 003's four loops.
//
// For each block B in order: solve f_B(x_B; x_solved) = 0 for the block's unknowns x_B by Newton,
// holding every other unknown at its current value (those of earlier blocks are already solved).
// When the blocks come from block_triangular_order(), a block's equations contain no unknown of a
// later block, so the blocks' roots together are a root of the whole system: sequential and full
// Newton converge to the same point, and differ only by their stopping tolerances.
//
// This generic version works on any DynamicSystem (it evaluates the whole residual and takes the
// block's rows). A model that wants speed writes its blocks as small fixed-size systems and runs
// Newton<Block, linalg::ClosedForm2x2> on each in turn.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::nonlinear {

struct SequentialNewtonResult {
  Eigen::VectorXd x;
  Status status = Status::converged;        // converged, or the status of the first block that failed
  int failed_block = -1;                    // index into the blocks, or -1
  std::vector<NewtonResult<Eigen::Dynamic>> blocks;  // one per block solved (or attempted)
  int iterations = 0;                       // summed over blocks
  double residual_norm = 0.0;               // ||f(x)||_inf of the whole system at the end
  int function_evaluations = 0;             // of the whole residual
  int jacobian_evaluations = 0;
};

// Receives every block's iterations; `block` is the index of the block being solved.
class SequentialObserver {
 public:
  virtual ~SequentialObserver() = default;
  virtual void on_block_iteration(int block, const NewtonRecord& record) = 0;
};

// Throws std::invalid_argument when the blocks do not cover each equation and unknown exactly once,
// a block is not square, x0 has the wrong size or the linear method is unknown.
SequentialNewtonResult sequential_newton(const DynamicSystem& system, const std::vector<Block>& blocks,
                                         const Eigen::VectorXd& x0, const NewtonOptions& options = {},
                                         const std::string& linear_method = "gepp",
                                         SequentialObserver* observer = nullptr);

}  // namespace numlab::nonlinear
