// watt-i.toml and stephenson-iii.toml: one degree of freedom, the blocks the sequential solve finds
// (Stephenson III has one that is not a dyad), every solver that applies agreeing, and every link
// length and body shape kept at every pose of a turn.
#include <catch2/catch.hpp>

#include <algorithm>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The largest violation at a pose of what the file states: every link's length, every pair of a
// body's joints at their local distance, every triple's signed area as in the local coordinates
// (so a body mirrored would fail).
double worst_closure_error(const LinkageModel& model, const Eigen::VectorXd& q) {
  const LinkageDescription& d = model.description();
  const JointPositions p = model.positions(q);
  const auto at = [&](int joint) { return p[static_cast<std::size_t>(joint)]; };
  double worst = 0.0;
  for (const LinkSpec& link : d.links) worst = std::max(worst, std::abs((at(link.second) - at(link.first)).norm() - link.length));
  for (const BodySpec& body : d.bodies) {
    const std::size_t n = body.joints.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const Eigen::Vector2d pij = at(body.joints[j]) - at(body.joints[i]), lij = body.local[j] - body.local[i];
        worst = std::max(worst, std::abs(pij.norm() - lij.norm()));
        for (std::size_t k = j + 1; k < n; ++k) {
          const Eigen::Vector2d pik = at(body.joints[k]) - at(body.joints[i]), lik = body.local[k] - body.local[i];
          worst = std::max(worst, std::abs(cross(pij, pik) - cross(lij, lik)));
        }
      }
    }
  }
  return worst;
}

std::vector<std::string> block_lines(const LinkageModel& model) {
  std::vector<std::string> lines;
  for (const auto& block : linkage_blocks(model)) lines.push_back(describe_block(model, block));
  return lines;
}

// Every solver that applies, over a whole turn, against the first one's poses; each pose closed.
void check_solvers_agree(const LinkageModel& model, const std::vector<std::string>& solvers) {
  // Residual tolerance from the conditioning over the turn (first solver's poses).
  const LinkageSweep first = linkage_sweep(LinkageSolver(model, {solvers.front(), "gepp", {}}), 0.0, 359.0, 1.0);
  REQUIRE(first.status == Status::converged);
  double worst_inverse = 0.0;
  for (const auto& pose : first.poses) worst_inverse = std::max(worst_inverse, inverse_jacobian_norm(model, pose.driver * deg, pose.q));
  const double tolerance = residual_tolerance_for(1e-10, worst_inverse, model.unknown_count());
  LinkageSolverOptions options{solvers.front(), "gepp", {}};
  options.newton.residual_tolerance = tolerance;
  options.tolerance_relative_to_size = false;  // derived from the conditioning, in length units
  options.newton.max_iterations = 50;
  const LinkageSweep reference = linkage_sweep(LinkageSolver(model, options), 0.0, 359.0, 1.0);
  REQUIRE(reference.status == Status::converged);
  for (const auto& pose : reference.poses) CHECK(worst_closure_error(model, pose.q) < 1e-9);
  for (const std::string& solver : solvers) {
    options.solver = solver;
    const LinkageSweep sweep = linkage_sweep(LinkageSolver(model, options), 0.0, 359.0, 1.0);
    INFO(solver << ", residual tolerance " << tolerance << " (max ||J^-1|| " << worst_inverse << ")");
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.branch_kept);
    double worst = 0.0, worst_closure = 0.0;
    for (std::size_t k = 0; k < sweep.poses.size(); ++k) {
      worst = std::max(worst, (sweep.poses[k].q - reference.poses[k].q).lpNorm<Eigen::Infinity>());
      worst_closure = std::max(worst_closure, worst_closure_error(model, sweep.poses[k].q));
    }
    CHECK(worst < 2e-10);  // both within 1e-10 of the root
    CHECK(worst_closure < 1e-9);
  }
}

// Every solver but analytic and GSL's finite-difference types (model_files.hpp).
std::vector<std::string> every_solver_but_analytic() {
  std::vector<std::string> out;
  for (const auto& name : linkage_solver_names()) {
    if (name != "analytic") out.push_back(name);
  }
  return out;
}

}  // namespace

TEST_CASE("watt-i.toml: mobility 1, every block a dyad or explicit", "[linkage-models]") {
  const LinkageModel model = model_file("watt-i");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  CHECK(block_lines(model) == std::vector<std::string>{"c from (G1): crank, explicit", "q from (G1, c): body point, explicit",
                                                       "p from (G2, c): dyad, closed form (circle-circle)",
                                                       "s from (c, p): body point, explicit",
                                                       "m from (q, s): dyad, closed form (circle-circle)"});
  auto solvers = every_solver_but_analytic();
  solvers.insert(solvers.begin(), "analytic");
  check_solvers_agree(model, solvers);
}

TEST_CASE("stephenson-iii.toml: mobility 1, and d, e, f form one 6x6 block that needs Newton", "[linkage-models]") {
  const LinkageModel model = model_file("stephenson-iii");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  CHECK(block_lines(model) == std::vector<std::string>{"a from (b): crank, explicit", "c from (b, a): body point, explicit",
                                                       "d, e, f from (a, c, m): 6x6 block, Newton"});
  const auto blocks = linkage_blocks(model);
  REQUIRE(blocks.size() == 3);
  CHECK(blocks[2].kind == BlockKind::newton);
  CHECK(blocks[2].joints.size() == 3);
  CHECK(blocks[2].rows_and_columns.equations.size() == 6);
  // analytic is refused, naming the block.
  try {
    const LinkageSolver analytic(model, {"analytic", "gepp", {}});
    FAIL("analytic accepted a model with a Newton block");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) ==
          "--solver analytic needs every block in closed form; block 3 (d, e, f from (a, c, m): 6x6 block, Newton) is not");
  }
  check_solvers_agree(model, every_solver_but_analytic());
}
