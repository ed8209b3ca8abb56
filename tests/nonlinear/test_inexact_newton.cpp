// Inexact Newton: the inner Gauss-Seidel solve stops at ||J dx + f|| <= eta_k ||f||
// (forcing_term.hpp), so helical valley converges where the old fixed inner tolerance stalled.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/forcing_term.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

namespace {

using Kind = ForcingOptions::Kind;
using GsNewton = Newton<DynamicReference, RuntimeLinearStep>;

ForcingOptions forcing_of(Kind kind, double eta = 0.1) {
  ForcingOptions forcing;
  forcing.kind = kind;
  forcing.eta = eta;
  return forcing;
}

NewtonOptions helical_options(ForcingOptions forcing) {
  NewtonOptions options;  // residual tolerance 1e-9, as `numlab solve nonlinear`
  options.max_iterations = 200;
  options.forcing = forcing;
  return options;
}

// One Newton iteration as the test saw it: x_k, f_k, the step taken and Newton's own record.
struct Iteration {
  Eigen::VectorXd x, f, dx;
  NewtonRecord record;
};

struct RecordKeeper final : GsNewton::Observer {
  std::vector<NewtonRecord> records;
  StepControl on_step(const GsNewton&, const NewtonRecord& record) override { records.push_back(record); return StepControl::proceed; }
};

struct Traced {
  NewtonResult<Eigen::Dynamic> result;
  std::vector<Iteration> iterations;
};

// Newton on a test problem from its standard start, one step() at a time, keeping x_k, f(x_k) and dx.
Traced traced_newton(const std::string& problem_name, const std::string& linear, const NewtonOptions& options) {
  const TestProblem problem = make_test_problem(problem_name);
  const DynamicReference system{*problem.system};
  GsNewton newton(system, options,
                  RuntimeLinearStep(linear, system.dimension(), inner_gauss_seidel_options(options.forcing)));
  RecordKeeper keeper;
  newton.set_observer(&keeper);
  newton.start(problem.standard_start);
  Traced traced;
  while (newton.running()) {
    Iteration iteration;
    iteration.x = newton.x();
    iteration.f = newton.residual();
    if (!newton.step() && keeper.records.size() < traced.iterations.size() + 1) break;
    iteration.dx = newton.x() - iteration.x;  // undamped: x_{k+1} = x_k + dx
    iteration.record = keeper.records.back();
    traced.iterations.push_back(iteration);
  }
  traced.result = newton.result();
  return traced;
}

// The residual test, recomputed from the problem itself (not Newton's number).
double residual_at(const std::string& problem_name, const Eigen::VectorXd& x) {
  const TestProblem problem = make_test_problem(problem_name);
  Eigen::VectorXd f;
  problem.system->residual(x, f);
  return f.lpNorm<Eigen::Infinity>();
}

}  // namespace

TEST_CASE("The defect, pinned: with the old fixed inner tolerance helical valley + Gauss-Seidel stalls above 1e-9",
          "[nonlinear][inexact][defect]") {
  const Traced stalled = traced_newton("helical-valley", "gauss-seidel", helical_options(forcing_of(Kind::none)));
  CHECK(stalled.result.status == Status::max_iterations);
  CHECK(stalled.result.reason == StopReason::iteration_limit);
  CHECK(stalled.result.iterations == 200);
  CHECK(residual_at("helical-valley", stalled.result.x) > 1e-9);
  // The inner solve stops on an absolute update of 1e-9, so once dx is below that, one sweep ends it.
  CHECK(stalled.iterations.back().record.linear_iterations == 1);
  CHECK(std::isnan(stalled.iterations.back().record.forcing_term));  // no eta_k without forcing
}

TEST_CASE("With a forcing term helical valley + Gauss-Seidel converges, residual test recomputed",
          "[nonlinear][inexact]") {
  for (const ForcingOptions forcing :
       {ForcingOptions{}, forcing_of(Kind::eisenstat_walker), forcing_of(Kind::constant, 0.1),
        forcing_of(Kind::constant, 1e-4)}) {
    INFO("kind " << static_cast<int>(forcing.kind) << " eta " << forcing.eta);
    const NewtonOptions options = helical_options(forcing);
    const Traced run = traced_newton("helical-valley", "gauss-seidel", options);
    REQUIRE(run.result.status == Status::converged);
    CHECK(residual_at("helical-valley", run.result.x) <= options.residual_tolerance);
    // The root is (1, 0, 0); J there is well conditioned, so the distance is of the residual's order.
    CHECK((run.result.x - Eigen::Vector3d(1.0, 0.0, 0.0)).lpNorm<Eigen::Infinity>() <= 1e-8);
  }
  // Under `numlab solve nonlinear`'s own default limit of 20 iterations too (the CLI's case).
  NewtonOptions cli_default;
  const Traced at_default = traced_newton("helical-valley", "gauss-seidel", cli_default);
  CHECK(at_default.result.status == Status::converged);
}

TEST_CASE("Each inner solve satisfies ||J dx + f|| <= eta_k ||f||, recomputed from J(x_k), f(x_k) and the step",
          "[nonlinear][inexact]") {
  const TestProblem problem = make_test_problem("helical-valley");
  for (const ForcingOptions forcing : {forcing_of(Kind::eisenstat_walker), forcing_of(Kind::constant, 0.1)}) {
    const Traced run = traced_newton("helical-valley", "gauss-seidel", helical_options(forcing));
    REQUIRE(run.result.status == Status::converged);
    for (const Iteration& iteration : run.iterations) {
      INFO("iteration " << iteration.record.iteration << " eta " << iteration.record.forcing_term);
      Eigen::MatrixXd J;
      problem.system->jacobian(iteration.x, J);
      const double linear_residual = (J * iteration.dx + iteration.f).lpNorm<Eigen::Infinity>();
      // x_{k+1} - x_k recovers dx up to one rounding of x_{k+1}: J times eps |x_{k+1}|.
      const double rounding = 4.0 * std::numeric_limits<double>::epsilon() * J.cwiseAbs().rowwise().sum().maxCoeff() *
                              (iteration.x + iteration.dx).lpNorm<Eigen::Infinity>();
      CHECK(iteration.record.linear_status == Status::converged);
      CHECK(linear_residual <= iteration.record.forcing_term * iteration.f.lpNorm<Eigen::Infinity>() + rounding);
    }
  }
}

TEST_CASE("Eisenstat-Walker's eta_k follows Choice 2 and its safeguards", "[nonlinear][inexact]") {
  const ForcingOptions ew;  // gamma 0.9, alpha 2, eta_0 0.5, eta_max 0.9
  const NewtonOptions options = helical_options(ew);
  const Traced run = traced_newton("helical-valley", "gauss-seidel", options);
  REQUIRE(run.iterations.size() >= 3);
  CHECK(run.iterations[0].record.forcing_term == ew.eta_initial);
  bool safeguard_a_used = false;
  for (std::size_t k = 1; k < run.iterations.size(); ++k) {
    const double f_now = run.iterations[k].f.lpNorm<Eigen::Infinity>();
    const double f_before = run.iterations[k - 1].f.lpNorm<Eigen::Infinity>();
    const double eta_before = run.iterations[k - 1].record.forcing_term;
    const double eta = run.iterations[k].record.forcing_term;
    const double choice2 = ew.gamma * std::pow(f_now / f_before, ew.alpha);
    const double floor = ew.gamma * std::pow(eta_before, ew.alpha);
    INFO("k " << k << " eta " << eta << " choice 2 " << choice2 << " floor " << floor);
    CHECK(eta <= ew.eta_max);
    CHECK(eta >= std::min(ew.eta_max, 0.5 * options.residual_tolerance / f_now));  // safeguard c
    if (floor > 0.1) {
      CHECK(eta >= std::min(floor, ew.eta_max));  // safeguard a
      safeguard_a_used = safeguard_a_used || choice2 < floor;
    }
    // Unsafeguarded: exactly Choice 2 (when none of the three bounds is active).
    if (floor <= 0.1 && choice2 < ew.eta_max && choice2 > 0.5 * options.residual_tolerance / f_now) {
      CHECK(eta == Approx(choice2).epsilon(1e-14));
    }
  }
  INFO("helical valley's first residual drop is steep enough to need safeguard a");
  CHECK(safeguard_a_used);

  // The safeguards by hand, on a made-up residual history.
  ForcingTerm term(ew);
  term.start();
  CHECK(term.next(1.0, 1e-9) == 0.5);                                      // eta_0
  CHECK(term.next(1e-3, 1e-9) == Approx(0.9 * 0.25));                     // a: 0.9 * 0.5^2 = 0.225 > 0.1
  CHECK(term.next(5e-4, 1e-9) == Approx(0.9 * 0.25));                     // choice 2: 0.225 (ratio 0.5)
  CHECK(term.next(2e-4, 1e-9) == Approx(std::max(0.9 * 0.16, 0.9 * std::pow(0.225, 2))));  // 0.144
  CHECK(term.next(2e-9, 1e-9) == Approx(0.25));                           // c: 0.5 tol / ||f|| = 0.25
  CHECK(term.next(1.9, 1e-9) == 0.9);                                      // b: eta_max
  CHECK_THROWS_AS(ForcingTerm(forcing_of(Kind::constant, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(ForcingTerm(forcing_of(Kind::constant, 0.0)), std::invalid_argument);
}

TEST_CASE("A direct inner solver ignores the forcing term: the same iterates, bitwise", "[nonlinear][inexact]") {
  for (const std::string linear : {"gepp", "gsl-lu", "eigen-lu"}) {
    const Traced none = traced_newton("helical-valley", linear, helical_options(forcing_of(Kind::none)));
    for (const ForcingOptions forcing : {forcing_of(Kind::eisenstat_walker), forcing_of(Kind::constant, 0.5)}) {
      const Traced forced = traced_newton("helical-valley", linear, helical_options(forcing));
      INFO(linear);
      REQUIRE(forced.iterations.size() == none.iterations.size());
      for (std::size_t k = 0; k < none.iterations.size(); ++k) {
        CHECK((forced.iterations[k].x.array() == none.iterations[k].x.array()).all());
        CHECK(std::isnan(forced.iterations[k].record.forcing_term));
      }
      CHECK((forced.result.x.array() == none.result.x.array()).all());
    }
  }
  // Fixed-size Newton with GEPP (the Jansen closure): no eta_k, identical result.
  using mechanisms::JansenClosure;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  NewtonOptions plain, forced;
  plain.forcing = forcing_of(Kind::none);
  forced.forcing = forcing_of(Kind::constant, 0.5);
  const auto a = newton_solve(closure, JansenClosure::seed_estimates(), plain);
  const auto b = newton_solve(closure, JansenClosure::seed_estimates(), forced);
  CHECK(a.iterations == b.iterations);
  CHECK((a.x.array() == b.x.array()).all());
}

TEST_CASE("Gauss-Seidel's residual stop: the first sweep with ||b - A x|| <= rtol ||b||; the update stop unchanged",
          "[linalg][gauss-seidel][inexact]") {
  Eigen::Matrix3d A;
  A << 4, 1, 0, 1, 3, -1, 0, -1, 5;
  const Eigen::Vector3d b(1, 2, 3);
  for (const double rtol : {0.5, 1e-3, 1e-10}) {
    linalg::GaussSeidelOptions options;
    options.relative_residual_tolerance = rtol;
    linalg::GaussSeidel<3> sweeps(options);
    sweeps.start(A, b);
    double residual_before = (b - A * sweeps.x()).lpNorm<Eigen::Infinity>();
    while (sweeps.step()) {
      residual_before = (b - A * sweeps.x()).lpNorm<Eigen::Infinity>();
      CHECK(residual_before > rtol * b.lpNorm<Eigen::Infinity>());  // not stopped while above target
    }
    INFO("rtol " << rtol);
    CHECK(sweeps.status() == Status::converged);
    CHECK((b - A * sweeps.x()).lpNorm<Eigen::Infinity>() <= rtol * b.lpNorm<Eigen::Infinity>());
  }
  // The setter is the option; zero gives back the update test.
  linalg::GaussSeidel<3> by_update, reset;
  reset.set_relative_residual_tolerance(1e-3);
  reset.set_relative_residual_tolerance(0.0);
  const auto u = by_update.solve(A, b), r = reset.solve(A, b);
  CHECK(u.iterations == r.iterations);
  CHECK((u.x.array() == r.x.array()).all());
  CHECK_THROWS_AS(reset.set_relative_residual_tolerance(-1.0), std::invalid_argument);
}

TEST_CASE("The Jansen sweep's inner Gauss-Seidel goes through the forcing term and agrees with the closed form",
          "[nonlinear][inexact][mechanisms]") {
  using mechanisms::JansenModel;
  for (const double tolerance : {1e-9, 1e-10}) {
    NewtonOptions options;
    options.residual_tolerance = tolerance;
    const auto gauss_seidel = mechanisms::make_jansen_solver(JansenModel::eight_equations, "full", "gauss-seidel", options);
    const auto gepp = mechanisms::make_jansen_solver(JansenModel::eight_equations, "full", "gepp", options);
    const auto inexact = mechanisms::crank_sweep(JansenModel::eight_equations, *gauss_seidel, 0.0, 359.0, 1.0);
    const auto exact = mechanisms::crank_sweep(JansenModel::eight_equations, *gepp, 0.0, 359.0, 1.0);
    INFO("tolerance " << tolerance);
    REQUIRE(inexact.status == Status::converged);
    REQUIRE(inexact.poses.size() == 360);
    CHECK(inexact.closed_form_verified);
    CHECK(inexact.orientation_kept);
    for (const auto& pose : inexact.poses) {
      CHECK(pose.outcome.status == Status::converged);
      CHECK(pose.outcome.residual_norm <= tolerance);
      CHECK(pose.closed_form_distance <= pose.closed_form_bound);  // what residual and conditioning justify
    }
    // The same accuracy as the exact inner solve: both within the bound that the tolerance justifies.
    CHECK(inexact.worst_closed_form_distance <= 1e-8);
    CHECK(exact.worst_closed_form_distance <= 1e-8);
  }
}

TEST_CASE("Sequential Newton's blocks with Gauss-Seidel inside take the forcing term too", "[nonlinear][inexact]") {
  using mechanisms::JansenClosure;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const AsDynamicSystem dynamic(closure);
  const Eigen::VectorXd start = JansenClosure::seed_estimates();
  const auto blocks = block_triangular_order(jacobian_pattern(dynamic, start));
  struct Etas final : SequentialNewton::Observer {
    std::vector<double> etas;
    StepControl on_step(const SequentialNewton&, const SequentialRecord& record) override {
      etas.push_back(record.newton.forcing_term);
      return StepControl::proceed;
    }
  };
  NewtonOptions options;
  options.residual_tolerance = 1e-10;
  Etas seen;
  const auto result = sequential_newton(dynamic, blocks, start, {options, LinearMethod::gauss_seidel}, &seen);
  REQUIRE(result.status == Status::converged);
  CHECK(result.residual_norm <= 1e-10);
  REQUIRE_FALSE(seen.etas.empty());
  for (const double eta : seen.etas) CHECK((eta > 0.0 && eta < 1.0));  // every inner solve was told an eta_k
  // With GEPP inside, none.
  Etas exact;
  sequential_newton(dynamic, blocks, start, {options, LinearMethod::gepp}, &exact);
  for (const double eta : exact.etas) CHECK(std::isnan(eta));
}

// Brown almost-linear (n = 30) from 100 x0: after four steps J^T J is so ill-conditioned that
// Gauss-Seidel's sweep limit comes before ||J dx + f|| <= eta_k ||f||, at every iteration. After three
// such steps in a row Newton stops, named, instead of spending the whole sweep limit again at every
// iteration (it once took 342 s for 4100).
TEST_CASE("An inner solve that runs out of sweeps before eta_k ends Newton as max_iterations (inner_limit)",
          "[nonlinear][inexact][honesty]") {
  const TestProblem problem = make_test_problem("brown-almost-linear", 30);
  const DynamicReference system{*problem.system};
  NewtonOptions options;
  options.max_iterations = 4100;
  GsNewton newton(system, options,
                  RuntimeLinearStep("gauss-seidel", 30, inner_gauss_seidel_options(options.forcing)));
  RecordKeeper keeper;
  newton.set_observer(&keeper);
  const auto result = newton.solve(100.0 * problem.standard_start);
  CHECK(result.status == Status::max_iterations);
  CHECK(result.reason == StopReason::inner_limit);
  CHECK(result.iterations < 20);  // three capped inner solves after the first four steps, long before 4100
  Eigen::VectorXd f;
  problem.system->residual(result.x, f);
  CHECK(f.lpNorm<Eigen::Infinity>() > options.residual_tolerance);  // no root was passed off
  CHECK_THAT(termination_line(result, options), Catch::Matchers::Contains("sweep limit"));
  // The last two steps taken were capped too: three in a row, the third one not taken.
  REQUIRE(keeper.records.size() >= 2);
  CHECK(keeper.records.back().linear_status == Status::max_iterations);
  CHECK(keeper.records[keeper.records.size() - 2].linear_status == Status::max_iterations);
}
