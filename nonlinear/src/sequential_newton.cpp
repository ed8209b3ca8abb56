#include "numlab/nonlinear/sequential_newton.hpp"

#include <stdexcept>

#include "numlab/nonlinear/linear_step.hpp"

namespace numlab::nonlinear {

namespace {

// One block as a system of its own: its unknowns are free, every other unknown is held fixed.
class BlockSystem final : public DynamicSystem {
 public:
  BlockSystem(const DynamicSystem& whole, const Block& block, Eigen::VectorXd& x, int& evaluations)
      : whole_(whole), block_(block), x_(x), evaluations_(evaluations) {}

  int dimension() const override { return static_cast<int>(block_.unknowns.size()); }

  void residual(const Eigen::VectorXd& block_x, Eigen::VectorXd& f) const override {
    place(block_x);
    whole_.residual(x_, full_f_);
    ++evaluations_;
    f.resize(dimension());
    for (int i = 0; i < dimension(); ++i) f(i) = full_f_(block_.equations[i]);
  }

  void jacobian(const Eigen::VectorXd& block_x, Eigen::MatrixXd& J) const override {
    place(block_x);
    whole_.jacobian(x_, full_J_);
    J.resize(dimension(), dimension());
    for (int i = 0; i < dimension(); ++i) {
      for (int j = 0; j < dimension(); ++j) J(i, j) = full_J_(block_.equations[i], block_.unknowns[j]);
    }
  }

 private:
  void place(const Eigen::VectorXd& block_x) const {
    for (int j = 0; j < dimension(); ++j) x_(block_.unknowns[j]) = block_x(j);
  }

  const DynamicSystem& whole_;
  const Block& block_;
  Eigen::VectorXd& x_;
  int& evaluations_;
  mutable Eigen::VectorXd full_f_;
  mutable Eigen::MatrixXd full_J_;
};

class BlockRelay final : public NewtonObserver<Eigen::Dynamic> {
 public:
  BlockRelay(SequentialObserver* observer, int block) : observer_(observer), block_(block) {}
  void on_iteration(const NewtonRecord& record) override { observer_->on_block_iteration(block_, record); }

 private:
  SequentialObserver* observer_;
  int block_;
};

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

SequentialNewtonResult sequential_newton(const DynamicSystem& system, const std::vector<Block>& blocks,
                                         const Eigen::VectorXd& x0, const NewtonOptions& options,
                                         const std::string& linear_method, SequentialObserver* observer) {
  const int n = system.dimension();
  if (x0.size() != n) {
    throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                std::to_string(n) + " unknowns");
  }
  require_partition(blocks, n);

  SequentialNewtonResult result;
  result.x = x0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Block& block = blocks[b];
    BlockSystem block_system(system, block, result.x, result.function_evaluations);
    Eigen::VectorXd block_start(block.unknowns.size());
    for (std::size_t j = 0; j < block.unknowns.size(); ++j) block_start(j) = result.x(block.unknowns[j]);

    Newton<BlockSystem, RuntimeLinearStep> newton(block_system, options,
                                                  RuntimeLinearStep(linear_method, block_system.dimension()));
    BlockRelay relay(observer, static_cast<int>(b));
    if (observer != nullptr) newton.set_observer(&relay);
    const NewtonResult<Eigen::Dynamic> block_result = newton.solve(block_start);
    for (std::size_t j = 0; j < block.unknowns.size(); ++j) result.x(block.unknowns[j]) = block_result.x(j);

    result.blocks.push_back(block_result);
    result.iterations += block_result.iterations;
    result.jacobian_evaluations += block_result.jacobian_evaluations;
    if (block_result.status != Status::converged) {
      result.status = block_result.status;
      result.failed_block = static_cast<int>(b);
      break;
    }
  }
  Eigen::VectorXd f;
  system.residual(result.x, f);
  result.residual_norm = f.lpNorm<Eigen::Infinity>();
  return result;
}

}  // namespace numlab::nonlinear
