// Fail fast, and recover: every solver stops soon past an assembly limit, GSL's types recover after
// a failed pose, and a big description (a chain of dyads) is solved in time about linear in its
// joints (the conditioning estimate of linkage_conditioning.hpp). Counts and verdicts here; the
// times are `numlab bench linkage-scaling`'s (docs/performance.md).
#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/dyad_chain.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "linkage_fixtures.hpp"

using namespace numlab::mechanisms;
using numlab::Status;
namespace fixtures = numlab::mechanisms::testing;

namespace {

LinkageModel chain_model(int joints) {
  return LinkageModel(parse_linkage_description(dyad_chain_description(joints), "chain.toml"));
}

double one_norm(const Eigen::MatrixXd& A) { return A.cwiseAbs().colwise().sum().maxCoeff(); }
double inf_norm(const Eigen::MatrixXd& A) { return A.cwiseAbs().rowwise().sum().maxCoeff(); }

}  // namespace

TEST_CASE("The dyad chain is a four-bar with a strip of closed-form dyads, assembled at its reference", "[linkage][scaling]") {
  for (int joints : {4, 5, 12, 100}) {
    const LinkageModel model = chain_model(joints);
    CHECK(model.unknown_count() == 2 * (joints - 2));
    const LinkageSolver solver(model, {});
    CHECK(solver.blocks().size() == static_cast<std::size_t>(joints - 2));  // the crank, then one dyad per joint
    for (std::size_t b = 1; b < solver.blocks().size(); ++b) CHECK(solver.blocks()[b].closed_form());
    Eigen::VectorXd f;
    model.residual(model.unknowns(model.rough_positions()), solver.reference_driver(), f);
    CHECK(f.lpNorm<Eigen::Infinity>() <= 1e-12);  // the file's positions are the reference pose
  }
  CHECK_THROWS(dyad_chain_description(3));
  CHECK_THROWS(dyad_chain_description(1001));
}

TEST_CASE("Hager's estimate of kappa_1 agrees with the exact one; sqrt(||J^-1||_1 ||J^-1||_inf) bounds ||J^-1||_2",
          "[linkage][scaling]") {
  for (int joints : {12, 60}) {
    const LinkageModel model = chain_model(joints);
    const LinkageSolver solver(model, {});
    Eigen::MatrixXd J;
    model.jacobian(solver.reference(), solver.reference_driver(), J);
    const Eigen::MatrixXd inverse = J.partialPivLu().inverse();
    const double kappa_1 = one_norm(J) * one_norm(inverse);
    const double bound_2 = std::sqrt(one_norm(inverse) * inf_norm(inverse));
    const LinkageConditioning exact = exact_linkage_conditioning(J);
    const LinkageConditioning estimate = estimated_linkage_conditioning(J);
    INFO(joints << " joints: kappa_1 " << kappa_1 << " estimated " << estimate.condition << "; kappa_2 " << exact.condition);
    // A lower bound, within Hager's usual factor 3 (here: exact to rounding).
    CHECK(estimate.condition <= kappa_1 * (1.0 + 1e-10));
    CHECK(estimate.condition >= kappa_1 / 3.0);
    CHECK(estimate.inverse_norm <= bound_2 * (1.0 + 1e-10));
    CHECK(estimate.inverse_norm >= bound_2 / 3.0);
    CHECK(bound_2 >= exact.inverse_norm * (1.0 - 1e-10));  // the 2-norm bound the sweep needs
  }
  // A singular J: both infinite, as the SVD's.
  Eigen::MatrixXd singular = Eigen::MatrixXd::Identity(4, 4);
  singular(3, 3) = 0.0;
  CHECK(std::isinf(estimated_linkage_conditioning(singular).condition));
  CHECK(std::isinf(exact_linkage_conditioning(singular).condition));
}

TEST_CASE("Small models keep the exact SVD; big ones the estimate", "[linkage][scaling]") {
  const LinkageModel small = chain_model(50);  // 96 unknowns: the exact SVD
  const LinkageSolver small_solver(small, {});
  Eigen::MatrixXd J;
  small.jacobian(small_solver.reference(), small_solver.reference_driver(), J);
  const LinkageConditioning exact = exact_linkage_conditioning(J);
  const LinkageConditioning used = linkage_conditioning(small, small_solver.reference_driver(), small_solver.reference());
  CHECK(used.condition == exact.condition);  // bit for bit
  CHECK(used.inverse_norm == exact.inverse_norm);

  const LinkageModel big = chain_model(300);  // 596 unknowns
  const LinkageSolver big_solver(big, {});
  big.jacobian(big_solver.reference(), big_solver.reference_driver(), J);
  const LinkageConditioning estimate = estimated_linkage_conditioning(J);
  const LinkageConditioning big_used = linkage_conditioning(big, big_solver.reference_driver(), big_solver.reference());
  CHECK(big_used.condition == estimate.condition);
  CHECK(std::isfinite(big_used.condition));
  CHECK(big_used.condition >= 1.0);
}

TEST_CASE("A sweep of a 300-joint chain assembles every pose, verified against the closed form", "[linkage][scaling]") {
  const LinkageModel model = chain_model(300);
  const LinkageSolver solver(model, {});
  const LinkageSweep sweep = linkage_sweep(solver, 60.0, 69.0, 1.0);
  REQUIRE(sweep.poses.size() == 10);
  CHECK(sweep.status == Status::converged);
  CHECK(sweep.closed_form_verified);
  CHECK(sweep.branch_kept);
  for (const LinkagePose& pose : sweep.poses) {
    CHECK(std::isfinite(pose.condition));
    CHECK(pose.closed_form_distance <= pose.closed_form_bound);
  }
}


namespace {
LinkageModel shipped(const std::string& name) {
  return LinkageModel(read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/" + name));
}
}  // namespace

TEST_CASE("Past an assembly limit, full Newton with Gauss-Seidel stops at its first capped inner solve that does not help",
          "[linkage][fail-fast]") {
  // The Mustang's limit is at 56.45 degrees (block 8 cannot close). From the pose at 56, predicted to
  // 57: J is nearly singular, Gauss-Seidel on the normal equations reaches its sweep limit, and the
  // inexact step makes ||f|| grow. Newton stops there, named, rather than after twenty iterations
  // of 100 000 sweeps each.
  const LinkageModel model = shipped("mustang.toml");
  const LinkageSolver gepp(model, {});
  const LinkageSweep at = linkage_sweep(gepp, 56.0, 56.0, 1.0);
  REQUIRE(at.status == Status::converged);
  LinkageSolverOptions options;
  options.linear = "gauss-seidel";
  const LinkageSolver seidel(model, options);
  const double t0 = model.driver_from_user(56.0), t1 = model.driver_from_user(57.0);
  const Eigen::VectorXd q = at.poses[0].q + linkage_velocity(model, t0, at.poses[0].q) * (t1 - t0);
  const LinkageSolution solution = seidel.solve(t1, q);
  INFO(numlab::to_string(solution.outcome.status) << " (" << numlab::nonlinear::to_string(solution.outcome.reason) << ") after "
                                                  << solution.outcome.iterations << " iterations");
  CHECK(solution.outcome.status == Status::max_iterations);
  CHECK(solution.outcome.reason == numlab::nonlinear::StopReason::inner_step_failed);
  CHECK(solution.outcome.iterations < options.newton.max_iterations);
  CHECK(solution.outcome.residual_norm > seidel.options().newton.residual_tolerance);  // no root claimed
  // Inside the range it still converges, as GEPP does.
  const LinkageSweep inside = linkage_sweep(seidel, 0.0, 10.0, 5.0);
  CHECK(inside.status == Status::converged);
}

TEST_CASE("GSL's types recover after the poses beyond a limit, as Newton does", "[linkage][fail-fast][gsl]") {
  // A sweep that starts beyond the Mustang's limit (70 degrees) and comes back into its range: every
  // solver assembles the same poses.
  const LinkageModel model = shipped("mustang.toml");
  const LinkageSweep newton = linkage_sweep(LinkageSolver(model, {}), 70.0, -60.0, -5.0);
  std::vector<bool> reference;
  for (const LinkagePose& pose : newton.poses) reference.push_back(pose.outcome.status == Status::converged);
  REQUIRE(std::count(reference.begin(), reference.end(), true) >= 15);
  for (const std::string type : {"hybridsj", "hybridj", "hybrids", "hybrid", "broyden", "dnewton", "newton", "gnewton"}) {
    LinkageSolverOptions options;
    options.solver = "gsl-" + type;
    const LinkageSweep sweep = linkage_sweep(LinkageSolver(model, options), 70.0, -60.0, -5.0);
    REQUIRE(sweep.poses.size() == reference.size());
    for (std::size_t k = 0; k < reference.size(); ++k) {
      INFO(type << " at " << sweep.poses[k].driver << ": " << numlab::to_string(sweep.poses[k].outcome.status));
      CHECK((sweep.poses[k].outcome.status == Status::converged) == reference[k]);
    }
  }
}

TEST_CASE("The sparse velocity and acceleration agree with the dense ones", "[linkage][scaling]") {
  const LinkageModel model = chain_model(60);
  const LinkageSolver solver(model, {});
  Eigen::VectorXd v, a, sparse_v, sparse_a;
  linkage_kinematics(model, solver.reference_driver(), solver.reference(), v, a);
  REQUIRE(sparse_linkage_kinematics(model, solver.reference_driver(), solver.reference(), sparse_v, sparse_a));
  CHECK((sparse_v - v).lpNorm<Eigen::Infinity>() <= 1e-9 * (1.0 + v.lpNorm<Eigen::Infinity>()));
  CHECK((sparse_a - a).lpNorm<Eigen::Infinity>() <= 1e-9 * (1.0 + a.lpNorm<Eigen::Infinity>()));
}

namespace {
// Full Newton with the given linear method inside.
LinkageSolverOptions full_newton_with(const std::string& linear) {
  LinkageSolverOptions options;
  options.linear = linear;
  return options;
}
}  // namespace

TEST_CASE("Poses past where the continuation failed are not solved again; each is named, and none assembles",
          "[linkage][fail-fast]") {
  // A non-Grashof four-bar (the crank stops where |AQ| = b + c, at 129.8 degrees) swept to 180:
  // the continuation from the last good pose fails once; the poses after it repeat that failure with
  // no work, and the closed form confirms that none of them assembles.
  const LinkageModel model(fixtures::four_bar(2.0, 3.0, 2.5, 4.0, 60.0));
  for (const std::string linear : {"gepp", "gauss-seidel"}) {
    const LinkageSolver solver(model, full_newton_with(linear));
    const LinkageSweep sweep = linkage_sweep(solver, 0.0, 180.0, 1.0);
    INFO(linear);
    REQUIRE(sweep.limits.size() == 1);
    const double limit = sweep.limits[0].driver;
    int not_tried = 0;
    for (const LinkagePose& pose : sweep.poses) {
      if (std::isnan(pose.not_tried_past)) continue;
      ++not_tried;
      CHECK(pose.outcome.status != Status::converged);
      CHECK(pose.outcome.iterations == 0);
      CHECK(pose.not_tried_past > limit);
      CHECK(pose.not_tried_past < pose.driver);
      // The closed form fails there too: past the fold nothing assembles.
      CHECK(solver.closed_form(model.driver_from_user(pose.driver), pose.q).failed_block >= 0);
    }
    // Every pose past the first failing one was skipped.
    const auto first_failed = std::find_if(sweep.poses.begin(), sweep.poses.end(), [](const LinkagePose& p) {
      return p.outcome.status != Status::converged;
    });
    REQUIRE(first_failed != sweep.poses.end());
    CHECK(std::isnan(first_failed->not_tried_past));  // the first one was tried
    CHECK(not_tried == static_cast<int>(sweep.poses.end() - first_failed) - 1);
  }
}

TEST_CASE("A solver that fails where the mechanism still assembles is not reported as a fold", "[linkage][fail-fast]") {
  // The Mustang's fold is at 56.45 degrees (GEPP finds it, block 8). Full Newton held to one or two
  // iterations per solve fails a little before it, where the poses need more (as Gauss-Seidel inside
  // Newton does, at 56.43, where J is too ill-conditioned for the normal equations' sweeps: too slow
  // for the sanitizer build). Each limit the sweep reports is either a fold the closed form confirms
  // (block named, the closed form fails just past it) or a solver failure where it still assembles.
  const LinkageModel model = shipped("mustang.toml");
  int solver_failures = 0;
  for (const int max_iterations : {100, 1, 2, 3}) {
    LinkageSolverOptions options;
    options.newton.max_iterations = max_iterations;
    const LinkageSolver solver(model, options);
    const LinkageSweep sweep = linkage_sweep(solver, 50.0, 60.0, 1.0);
    INFO(max_iterations << " iterations per solve");
    REQUIRE(sweep.limits.size() == 1);
    const LinkageLimit& limit = sweep.limits[0];
    const LinkagePose& before = sweep.poses[static_cast<std::size_t>(std::floor(limit.driver - 50.0))];
    REQUIRE(before.outcome.status == Status::converged);
    const double past = model.driver_from_user(limit.driver + limit.bracket);
    const bool closes_past = solver.closed_form(past, before.q).failed_block < 0;
    CHECK(limit.assembles_beyond == closes_past);
    if (!limit.assembles_beyond) {
      CHECK(std::abs(limit.driver - 56.45) <= 0.01);
      CHECK(limit.block == 7);  // block 8, P10's dyad
    }
    solver_failures += limit.assembles_beyond ? 1 : 0;
  }
  CHECK(solver_failures >= 1);  // both kinds were met
}

TEST_CASE("Beyond 100 unknowns the fast path's sparse J gives the dense path's poses and velocities", "[linkage][scaling]") {
  // A 60-joint chain: 116 unknowns, so the fast path keeps J sparse (linkage_fast_sparse.hpp); the
  // generic solver factors the dense J by GEPP. The same Newton iteration to rounding: the same
  // status and iteration count, positions within the conditioning's share of rounding.
  const LinkageModel model = chain_model(60);
  const LinkageSolver solver(model, {});
  REQUIRE(model.unknown_count() > linkage_exact_conditioning_limit);
  LinkageFastSolver fast(solver);
  for (const double crank_deg : {61.0, 75.0, 120.0}) {
    const double t = model.driver_from_user(crank_deg);
    const Eigen::VectorXd start = solver.reference();
    const LinkageSolution dense = solver.solve(t, start);
    Eigen::VectorXd q = start;
    const LinkageFastOutcome sparse = fast.solve(t, q);
    INFO(crank_deg << " deg: dense " << numlab::to_string(dense.outcome.status) << " in " << dense.outcome.iterations
                   << ", sparse " << numlab::to_string(sparse.outcome.status) << " in " << sparse.outcome.iterations);
    REQUIRE(dense.outcome.status == Status::converged);
    CHECK(sparse.outcome.status == Status::converged);
    CHECK(sparse.outcome.iterations == dense.outcome.iterations);
    const double kappa = linkage_conditioning(model, t, dense.q).condition;
    const double scale = 1.0 + dense.q.lpNorm<Eigen::Infinity>();
    CHECK((q - dense.q).lpNorm<Eigen::Infinity>() <= 100.0 * kappa * 1e-16 * scale + 10.0 * solver.options().newton.residual_tolerance);
    Eigen::VectorXd fast_velocity, velocity, acceleration;
    REQUIRE(fast.velocity(t, dense.q, fast_velocity));
    linkage_kinematics(model, t, dense.q, velocity, acceleration);
    CHECK((fast_velocity - velocity).lpNorm<Eigen::Infinity>() <= 100.0 * kappa * 1e-16 * (1.0 + velocity.lpNorm<Eigen::Infinity>()));
  }
}

TEST_CASE("A long chain's large kappa(J) is not a crossing: the derivative check says which it skipped", "[linkage][scaling]") {
  // A 500-joint chain: kappa(J) about 2e5 (it grows as the chain lengthens) with every dyad far from
  // its meeting point; the parallelogram on its crossing at 0 degrees: a dyad exactly there.
  const LinkageModel chain = chain_model(500);
  const LinkageSolver chain_solver(chain, {});
  const double t = chain.driver_from_user(65.0);
  const LinkageSolution pose = chain_solver.solve(t, chain_solver.reference());
  REQUIRE(pose.outcome.status == Status::converged);
  const DerivativeCheck long_chain = check_derivatives(chain_solver, t, pose.q);
  INFO("chain: kappa " << long_chain.condition);
  CHECK(long_chain.singular);  // beyond what J's kinematics resolve
  CHECK_FALSE(long_chain.near_meeting_point);

  const LinkageModel parallelogram(read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/parallelogram.toml"));
  const LinkageSolver solver(parallelogram, {});
  const LinkageSweep on_crossing = linkage_sweep(solver, 0.0, 0.0, 1.0);
  REQUIRE(on_crossing.status == Status::converged);
  const DerivativeCheck crossing = check_derivatives(solver, 0.0, on_crossing.poses[0].q);
  CHECK(crossing.singular);
  CHECK(crossing.near_meeting_point);
}
