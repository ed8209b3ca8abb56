// The fast path (linkage_fast_solver.hpp) against the generic solvers (linkage_solver.hpp) on every
// shipped model, with every solver it covers: the same statuses, reasons, iteration and residual
// evaluation counts and failing blocks, and joints as close as the residual test lets two solutions be.
//
// Two solutions q_a, q_b that both pass ||Phi||_inf <= tol lie within ||J^-1||_2 (||Phi(q_a)||_2 +
// ||Phi(q_b)||_2) of each other to first order; the tests allow twice that (the second-order term,
// and ||.||_inf <= ||.||_2), plus rounding, 64 eps |q| kappa(J).
#include <catch2/catch.hpp>

#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

bool all_closed_form(const LinkageModel& model) {
  for (const LinkageBlock& block : linkage_blocks(model)) {
    if (!block.closed_form()) return false;
  }
  return true;
}

// The explicit blocks (placed directly) a sequential solve reached: those before its failed block,
// and that block; all of them when none failed. None for the other solvers.
int explicit_blocks_reached(const LinkageSolver& solver, int failed_block) {
  if (solver.options().solver != "sequential") return 0;
  const auto& blocks = solver.blocks();
  const std::size_t reached = failed_block < 0 ? blocks.size() : static_cast<std::size_t>(failed_block) + 1;
  int count = 0;
  for (std::size_t b = 0; b < reached; ++b) count += blocks[b].placed_directly() ? 1 : 0;
  return count;
}

std::vector<std::string> fast_solvers(const LinkageModel& model) {
  std::vector<std::string> solvers{"full", "sequential"};
  if (all_closed_form(model)) solvers.push_back("analytic");
  return solvers;
}

LinkageSolverOptions options_for(const std::string& solver) {
  LinkageSolverOptions options{solver, "gepp", {}};
  options.newton.residual_tolerance = 1e-10;
  options.newton.max_iterations = 50;
  return options;
}

double residual_2norm(const LinkageModel& model, const Eigen::VectorXd& q, double t) {
  Eigen::VectorXd f;
  model.residual(q, t, f);
  return f.norm();
}

// How far apart two solutions at t that pass the residual test may be (see the header).
double allowed_distance(const LinkageModel& model, double t, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const LinkageConditioning conditioning = linkage_conditioning(model, t, a);
  const double scale = std::max(1.0, a.lpNorm<Eigen::Infinity>());
  return 2.0 * conditioning.inverse_norm * (residual_2norm(model, a, t) + residual_2norm(model, b, t)) +
         64.0 * std::numeric_limits<double>::epsilon() * scale * conditioning.condition;
}

// The driver values of the check (driver_range()): a whole turn about the reference, 5 degrees apart
// (poses that do not assemble included: both paths must fail alike there), or a cylinder's stroke.

}  // namespace

TEST_CASE("the fast path solves every shipped model as the generic solvers do, pose by pose", "[linkage-fast]") {
  for (const std::string& name : shipped_model_names()) {
    const LinkageModel model = model_file(name);
    for (const std::string& kind : fast_solvers(model)) {
      INFO(name << ", --solver " << kind);
      const LinkageSolver solver(model, options_for(kind));
      REQUIRE(LinkageFastSolver::applies(solver.options()));
      LinkageFastSolver fast(solver);
      // Starting points: the generic sweep's poses (an observer keeps it on the generic path).
      const double reference = model.driver_to_user(solver.reference_driver());
      const DriverRange range = driver_range(name);
      const LinkageSweep poses = linkage_sweep(solver, reference - range.half, reference + range.half, range.step,
                                               [](const LinkagePose&) { return numlab::StepControl::proceed; });
      int compared = 0, failures = 0;
      for (std::size_t k = 0; k + 1 < poses.poses.size(); ++k) {
        if (poses.poses[k].outcome.status != Status::converged) continue;
        // From pose k, straight to the next driver value (no predictor): a harder start than a sweep's.
        const double t = model.driver_from_user(poses.poses[k + 1].driver);
        const LinkageSolution generic = solver.solve(t, poses.poses[k].q);
        Eigen::VectorXd q = poses.poses[k].q;
        const LinkageFastOutcome quick = fast.solve(t, q);
        INFO("from " << poses.poses[k].driver << " to " << poses.poses[k + 1].driver << " deg");
        REQUIRE(quick.outcome.status == generic.outcome.status);
        CHECK(quick.outcome.reason == generic.outcome.reason);
        CHECK(quick.outcome.iterations == generic.outcome.iterations);
        CHECK(quick.outcome.function_evaluations == generic.outcome.function_evaluations);
        // J once per iteration on the fast path; with every residual on the generic one (DynamicSystem),
        // but for the explicit blocks' one evaluation of their rows each (placed directly, no J).
        CHECK(quick.outcome.jacobian_evaluations == quick.outcome.iterations);
        CHECK(generic.outcome.jacobian_evaluations ==
              generic.outcome.function_evaluations - explicit_blocks_reached(solver, generic.failed_block));
        CHECK(quick.failed_block == generic.failed_block);
        ++compared;
        if (generic.outcome.status != Status::converged) {
          ++failures;
          continue;
        }
        CHECK(quick.outcome.residual_norm <= solver.options().newton.residual_tolerance);
        // The residual it reports is Phi's at its result (sequential takes it from the blocks' rows).
        Eigen::VectorXd f;
        model.residual(q, t, f);
        CHECK(std::abs(quick.outcome.residual_norm - f.lpNorm<Eigen::Infinity>()) <=
              64.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, q.lpNorm<Eigen::Infinity>()));
        CHECK((q - generic.q).lpNorm<Eigen::Infinity>() <= allowed_distance(model, t, generic.q, q));
      }
      CHECK(compared >= 10);
      INFO(failures << " of " << compared << " solves failed alike");
    }
  }
}

TEST_CASE("a sweep on the fast path reports what the generic sweep reports", "[linkage-fast]") {
  for (const std::string& name : shipped_model_names()) {
    const LinkageModel model = model_file(name);
    for (const std::string& kind : fast_solvers(model)) {
      INFO(name << ", --solver " << kind);
      const LinkageSolver solver(model, options_for(kind));
      const double reference = model.driver_to_user(solver.reference_driver());
      const DriverRange range = driver_range(name);
      const double from = reference - range.half, to = reference + range.half;
      const LinkageSweep generic = linkage_sweep(solver, from, to, range.step, [](const LinkagePose&) { return numlab::StepControl::proceed; });
      const LinkageSweep fast = linkage_sweep(solver, from, to, range.step);  // no observer: the fast path
      REQUIRE(fast.poses.size() == generic.poses.size());
      CHECK(fast.status == generic.status);
      CHECK(fast.branch_kept == generic.branch_kept);
      CHECK(fast.flips == generic.flips);
      CHECK(fast.change_points == generic.change_points);
      REQUIRE(fast.limits.size() == generic.limits.size());
      for (std::size_t i = 0; i < fast.limits.size(); ++i) {
        CHECK(fast.limits[i].block == generic.limits[i].block);
        CHECK(std::abs(fast.limits[i].driver - generic.limits[i].driver) <= generic.limits[i].bracket);
      }
      for (std::size_t k = 0; k < fast.poses.size(); ++k) {
        const LinkagePose &a = fast.poses[k], &b = generic.poses[k];
        INFO("pose at " << b.driver);
        REQUIRE(a.outcome.status == b.outcome.status);
        CHECK(a.outcome.iterations == b.outcome.iterations);
        CHECK(a.step_halvings == b.step_halvings);
        CHECK(a.failed_block == b.failed_block);
        if (b.outcome.status == Status::converged) {
          const double t = model.driver_from_user(b.driver);
          CHECK((a.q - b.q).lpNorm<Eigen::Infinity>() <= allowed_distance(model, t, b.q, a.q));
          CHECK(a.signature == b.signature);
        }
      }
    }
  }
}

TEST_CASE("the fast velocity (block forward substitution) is the generic one (LU of the whole J)", "[linkage-fast]") {
  for (const std::string& name : shipped_model_names()) {
    const LinkageModel model = model_file(name);
    const LinkageSolver solver(model, options_for("sequential"));
    LinkageFastSolver fast(solver);
    const double t = solver.reference_driver();
    Eigen::VectorXd qdot;
    REQUIRE(fast.velocity(t, solver.reference(), qdot));
    const Eigen::VectorXd expected = linkage_velocity(model, t, solver.reference());
    // Two backward-stable solves of J v = -Phi_t differ by about kappa(J) eps |v|.
    const double kappa = linkage_conditioning(model, t, solver.reference()).condition;
    INFO(name << ": kappa(J) = " << kappa);
    CHECK((qdot - expected).lpNorm<Eigen::Infinity>() <=
          64.0 * kappa * std::numeric_limits<double>::epsilon() * std::max(1.0, expected.lpNorm<Eigen::Infinity>()));
  }
}

TEST_CASE("the fast path refuses what it does not cover, and bad starts as Newton does", "[linkage-fast]") {
  const LinkageModel model = model_file("four-bar");
  LinkageSolverOptions options = options_for("full");
  options.linear = "gauss-seidel";
  CHECK_FALSE(LinkageFastSolver::applies(options));
  CHECK_THROWS_AS(LinkageFastSolver(LinkageSolver(model, options)), std::invalid_argument);
  options = options_for("gsl-hybridsj");
  CHECK_FALSE(LinkageFastSolver::applies(options));
  options = options_for("sequential");
  options.newton.damped = true;
  CHECK_FALSE(LinkageFastSolver::applies(options));

  const LinkageSolver solver(model, options_for("full"));
  LinkageFastSolver fast(solver);
  Eigen::VectorXd short_start = Eigen::VectorXd::Zero(3);
  CHECK_THROWS_AS(fast.solve(0.0, short_start), std::invalid_argument);
  Eigen::VectorXd nan_start = solver.reference();
  nan_start(0) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(fast.solve(0.0, nan_start), std::invalid_argument);
  CHECK_THROWS_AS(solver.solve(0.0, nan_start), std::invalid_argument);
}
