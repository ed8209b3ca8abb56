#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "small_systems.hpp"

using namespace numlab;
using namespace numlab::nonlinear;
using namespace numlab::test;

namespace {

using Dynamic = DynamicReference;

NewtonOptions strict_options() {
  NewtonOptions options;
  options.residual_tolerance = 1e-10;
  options.max_iterations = 100;
  return options;
}

NewtonResult<Eigen::Dynamic> newton_on(const TestProblem& problem, const std::string& linear = "gepp",
                                       NewtonOptions options = strict_options()) {
  const Dynamic system{*problem.system};
  return Newton<Dynamic, RuntimeLinearStep>(system, options, RuntimeLinearStep(linear, system.dimension()))
      .solve(problem.standard_start);
}

// How far a computed root can be from the true one, given its residual: ||x - x*|| <~ ||J^-1|| ||f||.
double root_error_bound(const TestProblem& problem, const Eigen::VectorXd& x, double residual) {
  Eigen::MatrixXd J;
  problem.system->jacobian(x, J);
  const double inverse_norm = J.inverse().cwiseAbs().rowwise().sum().maxCoeff();
  return 10.0 * inverse_norm * residual + 1e-13 * (1.0 + x.lpNorm<Eigen::Infinity>());
}

// Newton records, kept for the tests that look at the rate of convergence.
struct Recorder : Newton<Dynamic, RuntimeLinearStep>::Observer {
  std::vector<NewtonRecord> records;
  StepControl on_step(const Newton<Dynamic, RuntimeLinearStep>&, const NewtonRecord& record) override {
    records.push_back(record);
    return StepControl::proceed;
  }
};

}  // namespace

TEST_CASE("Newton reaches the known root where J is nonsingular there", "[newton][mgh]") {
  for (const std::string name : {"rosenbrock", "freudenstein-roth", "powell-badly-scaled", "helical-valley"}) {
    const TestProblem problem = make_test_problem(name);
    const auto result = newton_on(problem);
    INFO(name << ": " << termination_line(result, strict_options()));
    REQUIRE(result.status == Status::converged);
    CHECK(result.residual_norm <= 1e-10);
    CHECK((result.x - *problem.known_root).lpNorm<Eigen::Infinity>() <=
          root_error_bound(problem, result.x, result.residual_norm));
  }
}

TEST_CASE("Newton is quadratic on Rosenbrock and only linear on Powell singular", "[newton][mgh][rate]") {
  const TestProblem rosenbrock = make_test_problem("rosenbrock");
  CHECK(newton_on(rosenbrock).iterations == 2);  // the second equation is linear: one step fixes x1

  // At Powell singular's root J is singular: each iteration only halves the error (and quarters
  // ||f||, whose terms are quadratic), so Newton needs ~20 iterations instead of ~5.
  const TestProblem powell = make_test_problem("powell-singular");
  const Dynamic system{*powell.system};
  Newton<Dynamic, RuntimeLinearStep> newton(system, strict_options(), RuntimeLinearStep("gepp", 4));
  Recorder recorder;
  newton.set_observer(&recorder);
  const auto result = newton.solve(powell.standard_start);
  REQUIRE(result.status == Status::converged);
  CHECK(result.iterations >= 15);
  const auto& r = recorder.records;
  for (std::size_t k = r.size() - 6; k < r.size(); ++k) {
    INFO("iteration " << r[k].iteration);
    CHECK(r[k].residual_norm / r[k - 1].residual_norm == Approx(0.25).margin(0.03));
  }
  // The error is about sqrt(||f||): far larger than the residual tolerance.
  const double distance = result.x.lpNorm<Eigen::Infinity>();
  CHECK(distance > 1e-7);
  CHECK(distance < 10.0 * std::sqrt(result.residual_norm));
}

TEST_CASE("Newton on Wood converges to the root of the system that is a saddle of Wood's function",
          "[newton][mgh][failure]") {
  // Every method, GSL's included, goes from (-3,-1,-3,-1) to the same point, not to (1,1,1,1).
  const TestProblem wood = make_test_problem("wood");
  const auto newton = newton_on(wood);
  const auto reference = gsl_multiroot_solve(*wood.system, wood.standard_start, "hybridsj", strict_options());
  REQUIRE(newton.status == Status::converged);
  REQUIRE(reference.status == Status::converged);
  CHECK((newton.x - reference.x).lpNorm<Eigen::Infinity>() <= 1e-8);
  CHECK((newton.x - *wood.known_root).lpNorm<Eigen::Infinity>() > 1.9);
  CHECK(newton.x(0) == Approx(-0.967974).epsilon(1e-5));
  CHECK(newton.x(1) == Approx(0.947139).epsilon(1e-5));
}

TEST_CASE("Newton agrees with GSL where no closed-form root is known", "[newton][mgh][reference]") {
  for (const std::string name : {"discrete-bvp", "broyden-tridiagonal", "trigonometric"}) {
    const TestProblem problem = make_test_problem(name);
    const auto newton = newton_on(problem);
    const auto reference = gsl_multiroot_solve(*problem.system, problem.standard_start, "newton", strict_options());
    INFO(name);
    REQUIRE(newton.status == Status::converged);
    REQUIRE(reference.status == Status::converged);
    CHECK((newton.x - reference.x).lpNorm<Eigen::Infinity>() <=
          root_error_bound(problem, newton.x, std::max(newton.residual_norm, reference.residual_norm)));
  }
  // The trigonometric system's standard start leads to a root other than x = 0.
  const TestProblem trigonometric = make_test_problem("trigonometric");
  CHECK(newton_on(trigonometric).x.lpNorm<Eigen::Infinity>() == Approx(0.18).margin(0.01));
}

TEST_CASE("Every inner linear solver gives the same Newton root", "[newton][linear]") {
  const TestProblem problem = make_test_problem("broyden-tridiagonal");
  const auto reference = newton_on(problem, "gepp");
  for (const std::string linear : {"gauss-seidel", "gsl-lu", "eigen-lu"}) {
    NewtonOptions options = strict_options();
    const auto result = newton_on(problem, linear, options);
    INFO(linear);
    REQUIRE(result.status == Status::converged);
    CHECK((result.x - reference.x).lpNorm<Eigen::Infinity>() <= root_error_bound(problem, result.x, 1e-10));
  }
  // The 2x2 closed form, compile-time chosen, on a fixed-size system.
  const auto closed_form =
      newton_solve(FixedRosenbrock{}, Vector2(-1.2, 1.0), strict_options(), linalg::ClosedForm2x2{});
  CHECK(closed_form.status == Status::converged);
  CHECK((closed_form.x - Vector2(1.0, 1.0)).lpNorm<Eigen::Infinity>() <= 1e-12);
  CHECK_THROWS_WITH(RuntimeLinearStep("inverse2x2", 3), Catch::Matchers::Contains("2x2"));
  CHECK_THROWS_WITH(RuntimeLinearStep("cholesky", 3), Catch::Matchers::Contains("unknown linear method"));
}

TEST_CASE("Newton's statuses: singular, non_finite, diverged, max_iterations, no_progress", "[newton][failure]") {
  const auto singular = newton_solve(SingularAtZero{}, Vector2(0.0, 3.0));
  CHECK(singular.status == Status::singular);
  CHECK(singular.reason == StopReason::singular_jacobian);
  CHECK(singular.iterations == 1);

  const auto at_nan_start = newton_solve(SquareRoot{}, Vector2(-1.0, 0.0));
  CHECK(at_nan_start.status == Status::non_finite);
  CHECK(at_nan_start.iterations == 0);
  const auto after_a_step = newton_solve(SquareRoot{}, Vector2(100.0, 0.0));
  CHECK(after_a_step.status == Status::non_finite);
  CHECK(after_a_step.iterations == 1);

  NewtonOptions divergence;
  divergence.divergence_factor = 1e3;
  divergence.max_iterations = 100;
  const auto diverged = newton_solve(CubeRoot{}, Vector2(1.0, 0.0), divergence);
  CHECK(diverged.status == Status::diverged);
  CHECK(diverged.residual_norm > 1e3);
  CHECK(diverged.iterations < 100);

  NewtonOptions one_iteration;
  one_iteration.max_iterations = 1;
  const auto limited = newton_solve(FixedRosenbrock{}, Vector2(-1.2, 1.0), one_iteration);
  CHECK(limited.status == Status::max_iterations);
  CHECK(limited.iterations == 1);
  CHECK_THAT(termination_line(limited, one_iteration), Catch::Matchers::Contains("MAX_ITERATIONS"));

  // Damping on Freudenstein-Roth: det J = 6 x2^2 - 8 x2 - 12 vanishes on the line x2 = -0.8968
  // (where ||f|| also has its non-root local minimum). The line search walks onto that line, the
  // Newton directions there stop being descent directions, and the step shrinks to nothing.
  NewtonOptions damped = strict_options();
  damped.damped = true;
  const TestProblem freudenstein = make_test_problem("freudenstein-roth");
  const Dynamic system{*freudenstein.system};
  const auto trapped = Newton<Dynamic, RuntimeLinearStep>(system, damped, RuntimeLinearStep("gepp", 2))
                           .solve(freudenstein.standard_start);
  CHECK(trapped.status == Status::no_progress);
  CHECK(trapped.residual_norm > 1.0);
  const double singular_line = (8.0 - std::sqrt(64.0 + 288.0)) / 12.0;  // the negative root of det J
  CHECK(trapped.x(1) == Approx(singular_line).epsilon(1e-4));
  Eigen::MatrixXd J;
  freudenstein.system->jacobian(trapped.x, J);
  CHECK(std::abs(J.determinant()) < 1e-3 * J.cwiseAbs().maxCoeff() * J.cwiseAbs().maxCoeff());
}

TEST_CASE("Damping cures Newton's overshoot on atan", "[newton][damped]") {
  // Plain Newton: |x| grows like |x|^3 per step until J = 1/(1 + x^2) underflows to 0.
  const TestProblem arctangent = make_test_problem("arctangent");
  const auto plain = newton_on(arctangent);
  CHECK(plain.status == Status::singular);
  CHECK(plain.x.lpNorm<Eigen::Infinity>() > 1e100);
  NewtonOptions damped = strict_options();
  damped.damped = true;
  const auto cured = newton_on(arctangent, "gepp", damped);
  REQUIRE(cured.status == Status::converged);
  CHECK(cured.x.lpNorm<Eigen::Infinity>() <= 1e-10);  // J(0) = I: the error is the residual
}

TEST_CASE("Hand-written Newton and GSL's newton take the same steps on every problem", "[newton][gsl][reference]") {
  // Both are undamped Newton with an LU solve: same iterates up to rounding, same iteration counts.
  // The ten problems from before the MINPACK set, where undamped Newton converges from the standard
  // start; on brown-almost-linear ours stops as diverged after 1 iteration (||f|| past 1e12 times its
  // start) while GSL's newton, without that test, wanders on to converge: test_minpack_gsl.cpp.
  for (const std::string name : {"rosenbrock", "freudenstein-roth", "powell-badly-scaled", "powell-singular", "wood",
                                 "helical-valley", "discrete-bvp", "trigonometric", "broyden-tridiagonal", "arctangent"}) {
    const TestProblem problem = make_test_problem(name);
    const auto ours = newton_on(problem);
    const auto gsl = gsl_multiroot_solve(*problem.system, problem.standard_start, "newton", strict_options());
    INFO(name << ": " << to_string(ours.status) << " after " << ours.iterations << ", GSL " << to_string(gsl.status)
              << " after " << gsl.iterations);
    if (name == "arctangent") continue;  // both run away; where each stops depends on the last overflow
    REQUIRE(ours.status == Status::converged);
    REQUIRE(gsl.status == Status::converged);
    CHECK(ours.iterations == gsl.iterations);
    CHECK((ours.x - gsl.x).lpNorm<Eigen::Infinity>() <= root_error_bound(problem, ours.x, 1e-10));
  }
  // The hard cases' counts, pinned: 43 iterations on Freudenstein-Roth, 19 on Powell singular.
  CHECK(newton_on(make_test_problem("freudenstein-roth")).iterations == 43);
  CHECK(newton_on(make_test_problem("powell-singular")).iterations == 19);
}

TEST_CASE("Newton rejects bad input", "[newton][bad-input]") {
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(newton_solve(FixedRosenbrock{}, Vector2(NAN, 1.0)), Contains("non-finite"));
  const TestProblem problem = make_test_problem("wood");
  const Dynamic system{*problem.system};
  Newton<Dynamic, RuntimeLinearStep> newton(system, {}, RuntimeLinearStep("gepp", 4));
  CHECK_THROWS_WITH(newton.solve(Eigen::VectorXd::Ones(3)), Contains("3 entries but the system has 4"));
  NewtonOptions negative;
  negative.residual_tolerance = -1.0;
  CHECK_THROWS_WITH(newton_solve(FixedRosenbrock{}, Vector2(0, 0), negative), Contains("finite number >= 0"));
  CHECK_THROWS_WITH(make_test_problem("beale"), Contains("unknown problem 'beale'"));
}

// The step test alone would say converged with ||f||_inf = 7.36. From x1 = 1e300 the
// trigonometric problem's f is a sum of cosines (bounded), J is tiny in column 1, and Newton's
// step in x1 is relatively far below 1e-12 (1 + ||x||): the iterates stop moving, with no root.
TEST_CASE("A small step is not a root: the step test alone gives no_progress, with the numbers",
          "[newton][honesty]") {
  const TestProblem problem = make_test_problem("trigonometric");
  Eigen::VectorXd start = Eigen::VectorXd::Ones(problem.system->dimension());
  start(0) = 1e300;
  const Dynamic system{*problem.system};
  const NewtonOptions options;  // the defaults: residual 1e-9, step 1e-12
  const auto stuck = Newton<Dynamic, RuntimeLinearStep>(system, options, RuntimeLinearStep("gepp", 10)).solve(start);
  CHECK(stuck.status == Status::no_progress);
  CHECK(stuck.reason == StopReason::step_small);
  CHECK(stuck.residual_norm > 1.0);  // 7.36: nowhere near the residual tolerance
  CHECK(stuck.step_norm <= options.step_tolerance * (1.0 + stuck.x.lpNorm<Eigen::Infinity>()));
  const std::string line = termination_line(stuck, options);
  CHECK_THAT(line, Catch::Matchers::Contains("NO_PROGRESS") && Catch::Matchers::Contains("||f||_inf = 7.36"));

  // GSL's newton from the same start: gsl_multiroot_test_delta passes, test_residual does not.
  const auto gsl = gsl_multiroot_solve(*problem.system, start, "newton", options);
  CHECK(gsl.status != Status::converged);
  CHECK(gsl.residual_norm > options.residual_tolerance);
}

TEST_CASE("Every Newton-type status converged passes the residual test", "[newton][honesty]") {
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    for (const NewtonResult<Eigen::Dynamic>& result :
         {newton_on(problem), gsl_multiroot_solve(*problem.system, problem.standard_start, "newton", strict_options()),
          gsl_multiroot_solve(*problem.system, problem.standard_start, "hybridsj", strict_options())}) {
      INFO(name << ": " << to_string(result.status));
      if (result.status == Status::converged) CHECK(result.residual_norm <= strict_options().residual_tolerance);
      if (result.reason == StopReason::step_small) CHECK(result.status == Status::no_progress);
    }
  }
}

TEST_CASE("A tolerance that is infinite, NaN or negative is misuse, for every Newton-type solver",
          "[newton][bad-input][honesty]") {
  using Catch::Matchers::Contains;
  const TestProblem problem = make_test_problem("rosenbrock");
  const FixedRosenbrock rosenbrock;
  for (const double bad : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), -1e-9}) {
    INFO("tolerance " << bad);
    NewtonOptions residual_bad, step_bad;
    residual_bad.residual_tolerance = bad;
    step_bad.step_tolerance = bad;
    for (const NewtonOptions& options : {residual_bad, step_bad}) {
      CHECK_THROWS_WITH(Newton<FixedRosenbrock>(rosenbrock, options), Contains("finite number >= 0"));
      CHECK_THROWS_WITH(GslMultiroot(*problem.system, "hybridsj", options), Contains("finite number >= 0"));
    }
  }
  NewtonOptions no_iterations;
  no_iterations.max_iterations = 0;
  CHECK_THROWS_WITH(GslMultiroot(*problem.system, "newton", no_iterations), Contains("at least 1"));
}
