#include "numlab/nonlinear/sequential_newton.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace numlab::nonlinear {

void BlockSystem::residual(const Eigen::VectorXd& block_x, Eigen::VectorXd& f) const {
  place(block_x);
  whole_.residual(x_, full_f_);
  ++evaluations_;
  f.resize(dimension());
  for (int i = 0; i < dimension(); ++i) f(i) = full_f_(block_->equations[i]);
}

void BlockSystem::jacobian(const Eigen::VectorXd& block_x, Eigen::MatrixXd& J) const {
  place(block_x);
  whole_.jacobian(x_, full_J_);
  J.resize(dimension(), dimension());
  for (int i = 0; i < dimension(); ++i) {
    for (int j = 0; j < dimension(); ++j) J(i, j) = full_J_(block_->equations[i], block_->unknowns[j]);
  }
}

void BlockSystem::place(const Eigen::VectorXd& block_x) const {
  for (int j = 0; j < dimension(); ++j) x_(block_->unknowns[j]) = block_x(j);
}

namespace {

void require_partition(const std::vector<Block>& blocks, int n) {
  std::vector<int> equation_uses(n, 0), unknown_uses(n, 0);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (blocks[b].equations.size() != blocks[b].unknowns.size() || blocks[b].unknowns.empty()) {
      throw std::invalid_argument("block " + std::to_string(b + 1) + " is not square and non-empty");
    }
    for (int e : blocks[b].equations) {
      if (e < 0 || e >= n) throw std::invalid_argument("block " + std::to_string(b + 1) + " names equation " +
                                                       std::to_string(e + 1) + " of a system of " + std::to_string(n));
      ++equation_uses[e];
    }
    for (int u : blocks[b].unknowns) {
      if (u < 0 || u >= n) throw std::invalid_argument("block " + std::to_string(b + 1) + " names unknown " +
                                                       std::to_string(u + 1) + " of a system of " + std::to_string(n));
      ++unknown_uses[u];
    }
  }
  for (int i = 0; i < n; ++i) {
    if (equation_uses[i] != 1) throw std::invalid_argument("equation " + std::to_string(i + 1) + " is in " +
                                                           std::to_string(equation_uses[i]) + " blocks, not 1");
    if (unknown_uses[i] != 1) throw std::invalid_argument("unknown " + std::to_string(i + 1) + " is in " +
                                                          std::to_string(unknown_uses[i]) + " blocks, not 1");
  }
}

}  // namespace

SequentialNewton::SequentialNewton(const DynamicSystem& system, const std::vector<Block>& blocks,
                                   SequentialNewtonOptions options)
    : system_(system), blocks_(blocks), options_(options),
      block_system_(system, result_.x, result_.function_evaluations) {
  require_tolerance(options_.newton.residual_tolerance, "residual tolerance");
  require_tolerance(options_.newton.step_tolerance, "step tolerance");
  if (options_.newton.max_iterations < 1) {
    throw std::invalid_argument("iteration limit must be at least 1, got " +
                                std::to_string(options_.newton.max_iterations));
  }
  require_partition(blocks_, system_.dimension());
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (options_.linear == LinearMethod::inverse2x2 && blocks_[b].unknowns.size() != 2) {
      throw std::invalid_argument("inverse2x2 needs 2x2 blocks, but block " + std::to_string(b + 1) + " has " +
                                  std::to_string(blocks_[b].unknowns.size()) + " unknowns");
    }
  }
}

void SequentialNewton::start(const Eigen::VectorXd& x0) {
  const int n = system_.dimension();
  if (x0.size() != n) {
    throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                std::to_string(n) + " unknowns");
  }
  result_ = SequentialNewtonResult{};  // status: running
  result_.x = x0;
  running_ = true;
  stopped_ = false;
  begin_block(0);
}

bool SequentialNewton::step() {
  if (!running_) return false;
  const int stepped_block = block();

  // 1. One Newton iteration on the current block, the other unknowns held.
  newton_->step();
  ++result_.iterations;
  const Block& current = blocks_[block_];
  for (std::size_t j = 0; j < current.unknowns.size(); ++j) result_.x(current.unknowns[j]) = newton_->x()(j);

  // 2. When the block's Newton has ended: a converged block hands on to the next, a failed one ends the solve.
  if (!newton_->running() && end_block()) begin_block(block_ + 1);

  if (observer_ != nullptr && relay_.record) {
    const StepControl control = observer_->on_step(*this, {stepped_block, *relay_.record});
    relay_.record.reset();
    if (control == StepControl::stop && running_) {  // the observer ended the run: no verdict
      running_ = false;
      stopped_ = true;
    }
  }
  return running_;
}

SequentialNewtonResult SequentialNewton::solve(const Eigen::VectorXd& x0) {
  start(x0);
  while (step()) {
  }
  return result_;
}

// Starts the Newton of block `first`, or of the next block that does not end where it starts
// (already solved); finishes the solve when no block is left.
void SequentialNewton::begin_block(std::size_t first) {
  for (block_ = first; block_ < blocks_.size(); ++block_) {
    const Block& block = blocks_[block_];
    block_system_.select(block);
    Eigen::VectorXd block_start(block.unknowns.size());
    for (std::size_t j = 0; j < block.unknowns.size(); ++j) block_start(j) = result_.x(block.unknowns[j]);
    newton_.emplace(block_system_, options_.newton,
                    RuntimeLinearStep(options_.linear, block_system_.dimension(),
                                      inner_gauss_seidel_options(options_.newton.forcing)));
    if (observer_ != nullptr) newton_->set_observer(&relay_);
    newton_->start(block_start);
    if (newton_->running()) return;
    if (!end_block()) return;
  }
  finish(Status::converged);
}

// Records the block's result and puts its unknowns into x. Returns whether it converged; if not,
// the solve ends with its status.
bool SequentialNewton::end_block() {
  const Block& block = blocks_[block_];
  NewtonResult<Eigen::Dynamic> block_result = newton_->result();
  for (std::size_t j = 0; j < block.unknowns.size(); ++j) result_.x(block.unknowns[j]) = block_result.x(j);
  result_.jacobian_evaluations += block_result.jacobian_evaluations;
  const Status status = block_result.status;
  result_.blocks.push_back(std::move(block_result));
  if (status == Status::converged) return true;
  result_.failed_block = static_cast<int>(block_);
  finish(status);
  return false;
}

// Every block converged is not yet a root of the whole system (blocks out of triangular order
// undo each other): converged only when the whole residual passes the residual test too.
void SequentialNewton::finish(Status status) {
  running_ = false;
  Eigen::VectorXd f;
  system_.residual(result_.x, f);
  result_.residual_norm = f.lpNorm<Eigen::Infinity>();
  if (status == Status::converged && !residual_small(result_.residual_norm, options_.newton.residual_tolerance)) {
    status = std::isfinite(result_.residual_norm) ? Status::no_progress : Status::non_finite;
  }
  result_.status = status;
}

SequentialNewtonResult sequential_newton(const DynamicSystem& system, const std::vector<Block>& blocks,
                                         const Eigen::VectorXd& x0, const SequentialNewtonOptions& options,
                                         SequentialNewton::Observer* observer) {
  SequentialNewton sequential(system, blocks, options);
  sequential.set_observer(observer);
  return sequential.solve(x0);
}

}  // namespace numlab::nonlinear
