// jansen.toml against the hand-coded Jansen leg (seed 000, mechanisms/jansen_leg.hpp): every joint
// to 1e-9 at every whole degree of a crank turn, with every solver numlab has.
#include <catch2/catch.hpp>

#include <algorithm>

#include "model_files.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

// The largest distance between the file's joints and the closed form's (names O, P1, A ... F), over
// the poses of a sweep; every pose must have converged.
double worst_joint_distance(const LinkageModel& model, const LinkageSweep& sweep) {
  const JansenLeg leg;
  double worst = 0.0;
  for (const LinkagePose& pose : sweep.poses) {
    const auto reference = leg.closed_form_joints(pose.driver * deg);
    REQUIRE(reference.has_value());
    for (int k = 0; k < jansen_joint_count; ++k) {
      const Eigen::Vector2d file_joint = joint_at(model, pose.q, jansen_joint_names[static_cast<std::size_t>(k)]);
      worst = std::max(worst, (file_joint - (*reference)[static_cast<std::size_t>(k)]).norm());
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("jansen.toml is fully dyadic: the blocks seed 000's analysis names", "[linkage-models]") {
  const LinkageModel model = model_file("jansen");
  CHECK(model.unknown_count() == 12);
  std::vector<std::string> lines;
  for (const auto& block : linkage_blocks(model)) lines.push_back(describe_block(model, block));
  CHECK(lines == std::vector<std::string>{"A from (O): crank, explicit", "B from (A, P1): dyad, closed form (circle-circle)",
                                          "C from (P1, B): body point, explicit",
                                          "D from (A, P1): dyad, closed form (circle-circle)",
                                          "E from (C, D): dyad, closed form (circle-circle)",
                                          "F from (D, E): body point, explicit"});
}

TEST_CASE("jansen.toml reproduces the hand-coded leg to 1e-9 at every degree with every solver", "[linkage-models]") {
  const LinkageModel model = model_file("jansen");
  // The tolerance from the conditioning: the largest ||J^-1||_2 over the turn (the closed form's poses).
  const LinkageSolver analytic(model, {"analytic", "gepp", {}});
  const LinkageSweep exact = linkage_sweep(analytic, 0.0, 359.0, 1.0);
  REQUIRE(exact.status == numlab::Status::converged);
  double worst_inverse = 0.0;
  for (const auto& pose : exact.poses) worst_inverse = std::max(worst_inverse, inverse_jacobian_norm(model, pose.driver * deg, pose.q));
  const double tolerance = residual_tolerance_for(1e-9, worst_inverse, model.unknown_count());
  INFO("max ||J^-1||_2 = " << worst_inverse << ", residual tolerance " << tolerance);
  CHECK(worst_joint_distance(model, exact) < 1e-9);

  struct Run {
    std::string solver, linear;
  };
  std::vector<Run> runs;
  for (const std::string linear : {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu"}) runs.push_back({"full", linear});
  for (const std::string& solver : linkage_solver_names()) {
    if (solver != "full") runs.push_back({solver, "gepp"});
  }
  for (const Run& run : runs) {
    LinkageSolverOptions options{run.solver, run.linear, {}};
    options.newton.residual_tolerance = tolerance;
    options.tolerance_relative_to_size = false;  // derived from the conditioning, in length units
    options.newton.max_iterations = 50;
    const LinkageSolver solver(model, options);
    const LinkageSweep sweep = linkage_sweep(solver, 0.0, 359.0, 1.0);
    INFO(run.solver << " / " << run.linear);
    REQUIRE(sweep.poses.size() == 360);
    CHECK(sweep.status == numlab::Status::converged);
    CHECK(sweep.branch_kept);
    if (sweep.status == numlab::Status::converged) CHECK(worst_joint_distance(model, sweep) < 1e-9);
  }
}
