#include <catch2/catch.hpp>
#include <algorithm>
#include <limits>

#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

using namespace numlab;
using namespace numlab::nonlinear;
using numlab::mechanisms::JansenClosure;

namespace {

int position_of(const std::vector<Block>& blocks, int unknown) {
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto& unknowns = blocks[b].unknowns;
    if (std::find(unknowns.begin(), unknowns.end(), unknown) != unknowns.end()) return static_cast<int>(b);
  }
  return -1;
}

}  // namespace

TEST_CASE("The block order of seed 000's 8x8 pattern is its four 2x2 blocks", "[block-order][jansen]") {
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const AsDynamicSystem dynamic(closure);
  const SparsityPattern pattern = jacobian_pattern(dynamic, Eigen::VectorXd(JansenClosure::seed_estimates()));
  const std::vector<Block> blocks = block_triangular_order(pattern);
  REQUIRE(blocks.size() == 4);
  // The blocks of seed 000's "Analysis" (0-based): (theta1, theta2) from eqs 1-2, (theta3, theta4)
  // from 3-4, (theta6, theta7) from 5-6, (theta5, theta8) from 7-8.
  const std::vector<std::pair<std::vector<int>, std::vector<int>>> seed_blocks = {
      {{0, 1}, {0, 1}}, {{2, 3}, {2, 3}}, {{4, 5}, {5, 6}}, {{6, 7}, {4, 7}}};
  for (const auto& [equations, unknowns] : seed_blocks) {
    const int b = position_of(blocks, unknowns[0]);
    REQUIRE(b >= 0);
    CHECK(blocks[b].unknowns == unknowns);
    CHECK(blocks[b].equations == equations);
  }
  // Each block comes after the blocks whose unknowns it reads.
  CHECK(position_of(blocks, 0) < position_of(blocks, 2));  // theta3,4 read theta1
  CHECK(position_of(blocks, 0) < position_of(blocks, 4));  // theta5,8 read theta1, theta3, theta7
  CHECK(position_of(blocks, 2) < position_of(blocks, 4));
  CHECK(position_of(blocks, 6) < position_of(blocks, 4));
}

TEST_CASE("Block orders of simple patterns, and structurally singular ones refused", "[block-order]") {
  SparsityPattern dense = SparsityPattern::Constant(3, 3, true);
  CHECK(block_triangular_order(dense).size() == 1);
  SparsityPattern lower = SparsityPattern::Constant(3, 3, false);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j <= i; ++j) lower(i, j) = true;
  }
  const auto chain = block_triangular_order(lower);
  REQUIRE(chain.size() == 3);
  CHECK(chain[0].unknowns == std::vector<int>{0});
  CHECK(chain[2].unknowns == std::vector<int>{2});
  // Equations 1 and 2 both contain only x1: no unknown is left for one of them.
  SparsityPattern singular = SparsityPattern::Constant(3, 3, false);
  singular(0, 0) = singular(1, 0) = singular(2, 1) = singular(2, 2) = true;
  CHECK_THROWS_WITH(block_triangular_order(singular), Catch::Matchers::Contains("structurally singular"));
  CHECK_THROWS_AS(block_triangular_order(SparsityPattern::Constant(2, 3, true)), std::invalid_argument);
}

TEST_CASE("Sequential and full Newton agree on the block-triangular Jansen system", "[sequential][jansen]") {
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const AsDynamicSystem dynamic(closure);
  const Eigen::VectorXd start = JansenClosure::seed_estimates();
  NewtonOptions options;
  options.residual_tolerance = 1e-12;

  const auto full = newton_solve(closure, JansenClosure::seed_estimates(), options);
  REQUIRE(full.status == Status::converged);

  const auto derived = block_triangular_order(jacobian_pattern(dynamic, start));
  const auto sequential = sequential_newton(dynamic, derived, start, {options});
  REQUIRE(sequential.status == Status::converged);
  CHECK(sequential.blocks.size() == 4);
  // Each block stopped at ||f_B|| <= 1e-12 with a well-conditioned 2x2 Jacobian, so both roots
  // are within about kappa * 1e-12 of the exact one.
  CHECK((sequential.x - Eigen::VectorXd(full.x)).lpNorm<Eigen::Infinity>() <= 1e-10);
  CHECK(sequential.residual_norm <= 1e-11);

  // The seed's own order, given by hand, gives the same root.
  const std::vector<Block> by_hand = {{{0, 1}, {0, 1}}, {{2, 3}, {2, 3}}, {{4, 5}, {5, 6}}, {{6, 7}, {4, 7}}};
  const auto seed_order = sequential_newton(dynamic, by_hand, start, {options, LinearMethod::inverse2x2});
  REQUIRE(seed_order.status == Status::converged);
  CHECK((seed_order.x - sequential.x).lpNorm<Eigen::Infinity>() <= 1e-10);

  // Blocks that miss an unknown are refused.
  const std::vector<Block> incomplete(by_hand.begin(), by_hand.begin() + 3);
  CHECK_THROWS_WITH(sequential_newton(dynamic, incomplete, start), Catch::Matchers::Contains("in 0 blocks"));
}

TEST_CASE("The Jansen closure Jacobian agrees with finite differences", "[jacobian-check][jansen]") {
  const JansenClosure closure(0.7);
  const AsDynamicSystem dynamic(closure);
  const JacobianCheck check = check_jacobian(dynamic, Eigen::VectorXd(JansenClosure::seed_estimates()));
  INFO(describe_worst_entry(check));
  CHECK(check.agrees);
  CHECK(check.autodiff.size() == 0);  // no AutoDiff version: finite differences are the reference
}

namespace {

// f = (x1 - x2, x2 - 1): the root is (1, 1). Blocks {f1: x1} then {f2: x2} are out of triangular
// order (f1 contains the later unknown x2).
struct Chained final : DynamicSystem {
  int dimension() const override { return 2; }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override {
    f.resize(2);
    f << x(0) - x(1), x(1) - 1.0;
  }
  void jacobian(const Eigen::VectorXd&, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << 1.0, -1.0, 0.0, 1.0;
  }
};

}  // namespace

TEST_CASE("Sequential Newton says converged only when the whole residual is small", "[sequential][honesty]") {
  const Chained system;
  const std::vector<Block> out_of_order = {{{0}, {0}}, {{1}, {1}}};
  // From (0, 5): block 1 sets x1 = 5 (x2 held at 5), block 2 sets x2 = 1; f1 is then 4.
  const auto result = sequential_newton(system, out_of_order, Eigen::Vector2d(0.0, 5.0));
  REQUIRE(result.blocks.size() == 2);
  for (const auto& block : result.blocks) CHECK(block.status == Status::converged);
  CHECK(result.residual_norm == 4.0);
  CHECK(result.status == Status::no_progress);
  // In triangular order (x2 first) the same system is solved.
  const std::vector<Block> in_order = {{{1}, {1}}, {{0}, {0}}};
  const auto solved = sequential_newton(system, in_order, Eigen::Vector2d(0.0, 5.0));
  CHECK(solved.status == Status::converged);
  CHECK(solved.residual_norm <= NewtonOptions{}.residual_tolerance);

  // Misuse: a tolerance that is not a finite number >= 0, refused at construction.
  NewtonOptions infinite;
  infinite.residual_tolerance = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(SequentialNewton(system, in_order, {infinite}), Catch::Matchers::Contains("finite number >= 0"));
}
