#include "numlab/nonlinear/block_order.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

namespace numlab::nonlinear {

namespace {

// 1. Matching by augmenting paths: matched_unknown[e] is the unknown paired with equation e.
std::vector<int> perfect_matching(const SparsityPattern& pattern) {
  const int n = static_cast<int>(pattern.rows());
  std::vector<int> matched_unknown(n, -1), matched_equation(n, -1);
  std::vector<bool> visited(n);
  // Tries to find an unknown for `equation`, re-pairing earlier equations if needed.
  std::function<bool(int)> augment = [&](int equation) {
    for (int unknown = 0; unknown < n; ++unknown) {
      if (!pattern(equation, unknown) || visited[unknown]) continue;
      visited[unknown] = true;
      if (matched_equation[unknown] < 0 || augment(matched_equation[unknown])) {
        matched_equation[unknown] = equation;
        matched_unknown[equation] = unknown;
        return true;
      }
    }
    return false;
  };
  for (int equation = 0; equation < n; ++equation) {
    std::fill(visited.begin(), visited.end(), false);
    if (!augment(equation)) {
      throw std::invalid_argument("the system is structurally singular: equation " + std::to_string(equation + 1) +
                                  " cannot be paired with an unknown of its own");
    }
  }
  return matched_unknown;
}

}  // namespace

std::vector<Block> block_triangular_order(const SparsityPattern& pattern) {
  if (pattern.rows() != pattern.cols() || pattern.rows() == 0) {
    throw std::invalid_argument("a sparsity pattern must be square and non-empty, got " +
                                std::to_string(pattern.rows()) + "x" + std::to_string(pattern.cols()));
  }
  const int n = static_cast<int>(pattern.rows());
  const std::vector<int> matched_unknown = perfect_matching(pattern);
  std::vector<int> equation_of(n);
  for (int equation = 0; equation < n; ++equation) equation_of[matched_unknown[equation]] = equation;

  // 2-3. Tarjan's strongly connected components over "unknown u depends on unknown v".
  std::vector<int> index(n, -1), lowlink(n, 0), stack;
  std::vector<bool> on_stack(n, false);
  std::vector<Block> blocks;
  int next_index = 0;
  std::function<void(int)> visit = [&](int u) {
    index[u] = lowlink[u] = next_index++;
    stack.push_back(u);
    on_stack[u] = true;
    for (int v = 0; v < n; ++v) {
      if (v == u || !pattern(equation_of[u], v)) continue;  // u's equation does not contain v
      if (index[v] < 0) {
        visit(v);
        lowlink[u] = std::min(lowlink[u], lowlink[v]);
      } else if (on_stack[v]) {
        lowlink[u] = std::min(lowlink[u], index[v]);
      }
    }
    if (lowlink[u] != index[u]) return;
    // u is the root of a component: pop it. Components complete sinks-first (4.).
    Block block;
    int member = -1;
    do {
      member = stack.back();
      stack.pop_back();
      on_stack[member] = false;
      block.unknowns.push_back(member);
    } while (member != u);
    std::sort(block.unknowns.begin(), block.unknowns.end());
    for (int unknown : block.unknowns) block.equations.push_back(equation_of[unknown]);
    std::sort(block.equations.begin(), block.equations.end());
    blocks.push_back(std::move(block));
  };
  for (int u = 0; u < n; ++u) {
    if (index[u] < 0) visit(u);
  }
  return blocks;
}

SparsityPattern jacobian_pattern(const DynamicSystem& system, const Eigen::VectorXd& x) {
  Eigen::MatrixXd at_x, at_perturbed;
  system.jacobian(x, at_x);
  // A deterministic, irregular perturbation (no entry of the pattern depends on luck).
  Eigen::VectorXd perturbed = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) perturbed(i) += 0.1 + 0.0137 * static_cast<double>(i + 1);
  system.jacobian(perturbed, at_perturbed);
  return (at_x.array() != 0.0) || (at_perturbed.array() != 0.0);
}

}  // namespace numlab::nonlinear
