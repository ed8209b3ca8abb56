#pragma once
// Sequential (block-by-block) Newton: seed 000's four 2x2 blocks, seed 003's four loops.
//
// For each block B in order: solve f_B(x_B; x_solved) = 0 for the block's unknowns x_B by Newton,
// holding every other unknown at its current value (those of earlier blocks are already solved).
// When the blocks come from block_triangular_order(), a block's equations contain no unknown of a
// later block, so the blocks' roots together are a root of the whole system: sequential and full
// Newton converge to the same point, and differ only by their stopping tolerances.
//
// A stepper (numlab/solver.hpp): one step() is one Newton iteration of the current block; when
// that block's Newton ends, a converged block hands on to the next one and a failed block ends
// the solve. x() is the whole vector.
//
// This generic version works on any DynamicSystem (it evaluates the whole residual and takes the
// block's rows). A model that wants speed writes its blocks as small fixed-size systems and runs
// Newton<Block, linalg::ClosedForm2x2> on each in turn.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/solver.hpp"

namespace numlab::nonlinear {

struct SequentialNewtonOptions {
  NewtonOptions newton;                     // every block's Newton
  LinearMethod linear = LinearMethod::gepp;  // every block's inner solve
};

struct SequentialNewtonResult {
  Eigen::VectorXd x;
  Status status = Status::running;          // converged (every block did, and ||f||_inf <= tolerance),
                                            // the status of the first block that failed, or
                                            // no_progress (blocks converged, whole residual not small)
  int failed_block = -1;                    // index into the blocks, or -1
  std::vector<NewtonResult<Eigen::Dynamic>> blocks;  // one per block solved (or attempted)
  int iterations = 0;                       // summed over blocks
  double residual_norm = 0.0;               // ||f(x)||_inf of the whole system at the end
  int function_evaluations = 0;             // of the whole residual
  int jacobian_evaluations = 0;
};

// One row of the trace: the block being solved (an index into the blocks) and its Newton's record.
struct SequentialRecord {
  int block;
  NewtonRecord newton;
};

// One block as a system of its own: its unknowns are free, every other unknown is held at its
// value in the whole vector x. Every evaluation writes the block's unknowns into x.
class BlockSystem final : public DynamicSystem {
 public:
  BlockSystem(const DynamicSystem& whole, Eigen::VectorXd& x, int& evaluations)
      : whole_(whole), x_(x), evaluations_(evaluations) {}
  void select(const Block& block) { block_ = &block; }

  int dimension() const override { return static_cast<int>(block_->unknowns.size()); }
  void residual(const Eigen::VectorXd& block_x, Eigen::VectorXd& f) const override;
  void jacobian(const Eigen::VectorXd& block_x, Eigen::MatrixXd& J) const override;

 private:
  void place(const Eigen::VectorXd& block_x) const;

  const DynamicSystem& whole_;
  const Block* block_ = nullptr;
  Eigen::VectorXd& x_;
  int& evaluations_;
  mutable Eigen::VectorXd full_f_;
  mutable Eigen::MatrixXd full_J_;
};

class SequentialNewton {
 public:
  using Observer = StepObserver<SequentialNewton, SequentialRecord>;
  using BlockNewton = Newton<BlockSystem, RuntimeLinearStep>;

  // system and blocks must outlive the stepper. Throws std::invalid_argument when the blocks do not
  // cover each equation and unknown exactly once, a block is not square, or the linear method is
  // inverse2x2 and a block is not 2x2, or for Newton options that Newton rejects (a tolerance
  // negative or not finite, an iteration limit below 1).
  SequentialNewton(const DynamicSystem& system, const std::vector<Block>& blocks, SequentialNewtonOptions options = {});
  SequentialNewton(const DynamicSystem&, std::vector<Block>&&, SequentialNewtonOptions = {}) = delete;
  SequentialNewton(const DynamicSystem&&, const std::vector<Block>&, SequentialNewtonOptions = {}) = delete;
  SequentialNewton(const DynamicSystem&&, std::vector<Block>&&, SequentialNewtonOptions = {}) = delete;
  SequentialNewton(const SequentialNewton&) = delete;
  SequentialNewton& operator=(const SequentialNewton&) = delete;

  void set_observer(Observer* observer) { observer_ = observer; }

  // Sets x = x0 and starts the first block. Throws std::invalid_argument for a wrong size.
  void start(const Eigen::VectorXd& x0);
  // One Newton iteration of the current block. Returns false once the solve has ended.
  bool step();
  SequentialNewtonResult solve(const Eigen::VectorXd& x0);
  const SequentialNewtonResult& result() const { return result_; }

  bool running() const { return running_; }
  Status status() const { return result_.status; }  // running until the last block has ended
  bool stopped() const { return stopped_; }
  int iterations() const { return result_.iterations; }
  const Eigen::VectorXd& x() const { return result_.x; }
  int block() const { return static_cast<int>(block_); }  // the block being solved (its index)
  const SequentialNewtonOptions& options() const { return options_; }

 private:
  // Keeps the block Newton's record of its step, for step() to send on as a SequentialRecord once
  // x and the status are up to date. (Newton sends none for an iteration that could not move.)
  struct Relay final : BlockNewton::Observer {
    std::optional<NewtonRecord> record;
    StepControl on_step(const BlockNewton&, const NewtonRecord& sent) override {
      record = sent;
      return StepControl::proceed;
    }
  };

  void begin_block(std::size_t block);
  bool end_block();
  void finish(Status status);

  const DynamicSystem& system_;
  const std::vector<Block>& blocks_;
  SequentialNewtonOptions options_;
  Observer* observer_ = nullptr;
  SequentialNewtonResult result_;
  BlockSystem block_system_;
  std::optional<BlockNewton> newton_;
  std::size_t block_ = 0;
  bool running_ = false;
  bool stopped_ = false;
  Relay relay_;
};

// A SequentialNewton's solve(): throws as its constructor and start() do.
SequentialNewtonResult sequential_newton(const DynamicSystem& system, const std::vector<Block>& blocks,
                                         const Eigen::VectorXd& x0, const SequentialNewtonOptions& options = {},
                                         SequentialNewton::Observer* observer = nullptr);

}  // namespace numlab::nonlinear
