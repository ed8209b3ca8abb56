// Explicit blocks (a crank, a body point, a driven slider: linkage_blocks.hpp) are placed by their
// formula, with no Newton iteration, by the generic sequential solver and by its fast path alike;
// their rows are still checked at the placed joint, so an impossible input is a named failure.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

LinkageSolverOptions sequential_options() {
  LinkageSolverOptions options{"sequential", "gepp", {}};
  options.newton.residual_tolerance = 1e-10;
  options.newton.max_iterations = 50;
  return options;
}

int first_block_of_kind(const LinkageSolver& solver, BlockKind kind) {
  for (std::size_t b = 0; b < solver.blocks().size(); ++b) {
    if (solver.blocks()[b].kind == kind) return static_cast<int>(b);
  }
  return -1;
}

}  // namespace

TEST_CASE("an explicit block is placed directly: a start far off on its joints costs no iteration", "[linkage-fast]") {
  const LinkageModel model = model_file("jansen");
  const LinkageSolver solver(model, sequential_options());
  LinkageFastSolver fast(solver);
  REQUIRE(first_block_of_kind(solver, BlockKind::crank) >= 0);
  REQUIRE(first_block_of_kind(solver, BlockKind::body_point) >= 0);
  // The reference pose with every explicit block's joint moved by (1, -1): the dyads' joints are
  // right, so once the explicit joints are placed every remaining row is at rounding level.
  Eigen::VectorXd start = solver.reference();
  for (const LinkageBlock& block : solver.blocks()) {
    if (!block.placed_directly()) continue;
    start.segment<2>(model.column_of(block.joints[0])) += Eigen::Vector2d(1.0, -1.0);
  }
  const double t = solver.reference_driver();
  const LinkageSolution generic = solver.solve(t, start);
  Eigen::VectorXd q = start;
  const LinkageFastOutcome quick = fast.solve(t, q);
  CHECK(generic.outcome.status == Status::converged);
  CHECK(quick.outcome.status == Status::converged);
  CHECK(generic.outcome.iterations == 0);  // one Newton step each before the explicit blocks were placed
  CHECK(quick.outcome.iterations == 0);
  // The crank's joint against its formula, from the description: p_A = p_O + r (cos, sin)(t + offset).
  const int crank = first_block_of_kind(solver, BlockKind::crank);
  const Constraint& c = model.constraints()[static_cast<std::size_t>(solver.blocks()[static_cast<std::size_t>(crank)].constraints[0])];
  const Eigen::Vector2d centre = model.description().joints[static_cast<std::size_t>(c.joints[0])].position;
  const Eigen::Vector2d expected = centre + c.length * Eigen::Vector2d(std::cos(t + c.offset), std::sin(t + c.offset));
  const double rounding = 16.0 * std::numeric_limits<double>::epsilon() * (centre.norm() + c.length);
  CHECK((generic.q.segment<2>(model.column_of(c.joints[1])) - expected).lpNorm<Eigen::Infinity>() <= rounding);
  CHECK((q.segment<2>(model.column_of(c.joints[1])) - expected).lpNorm<Eigen::Infinity>() <= rounding);
  CHECK((generic.q - solver.reference()).lpNorm<Eigen::Infinity>() <= 1e-9);
}

TEST_CASE("an explicit block whose rows fail the residual test is a named failure, not a success", "[linkage-fast]") {
  const LinkageModel model = model_file("jansen");
  const LinkageSolver solver(model, sequential_options());
  LinkageFastSolver fast(solver);
  // A driver value that is not finite places the crank's joint at NaN: its rows are not finite.
  const double t = std::numeric_limits<double>::quiet_NaN();
  const LinkageSolution generic = solver.solve(t, solver.reference());
  Eigen::VectorXd q = solver.reference();
  const LinkageFastOutcome quick = fast.solve(t, q);
  const int crank = first_block_of_kind(solver, BlockKind::crank);
  CHECK(generic.outcome.status == Status::non_finite);
  CHECK(quick.outcome.status == Status::non_finite);
  CHECK(generic.failed_block == crank);
  CHECK(quick.failed_block == crank);
  CHECK(generic.outcome.iterations == 0);
  CHECK(quick.outcome.iterations == 0);
}
