// The chord method (NewtonOptions::reuse_jacobian = K): J evaluated and factored every K iterations,
// GEPP's kept factors reused between. K = 1 is Newton, iterate for iterate; K > 1 takes more
// iterations and fewer factorizations; where the old J points the wrong way it fails with a status.

#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/newton.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

namespace {

using Dynamic = DynamicReference;
using DynamicNewton = Newton<Dynamic, RuntimeLinearStep>;

NewtonOptions chord_options(int every) {
  NewtonOptions options;
  options.max_iterations = 100;
  options.reuse_jacobian = every;
  return options;
}

// x after every iteration, and the trace's refactored flags.
struct Iterates : DynamicNewton::Observer {
  std::vector<Eigen::VectorXd> x;
  std::vector<int> refactored;
  StepControl on_step(const DynamicNewton& newton, const NewtonRecord& record) override {
    x.push_back(newton.x());
    refactored.push_back(record.jacobian_refactored);
    return StepControl::proceed;
  }
};

struct ChordRun {
  NewtonResult<Eigen::Dynamic> result;
  Iterates iterates;
};

ChordRun run_chord(const TestProblem& problem, NewtonOptions options, const std::string& linear = "gepp") {
  const Dynamic system{*problem.system};
  DynamicNewton newton(system, options, RuntimeLinearStep(linear, system.dimension()));
  ChordRun run;
  newton.set_observer(&run.iterates);
  run.result = newton.solve(problem.standard_start);
  return run;
}

}  // namespace

TEST_CASE("Chord with K = 1 is Newton: the same iterates bit for bit, one factorization each", "[newton][chord]") {
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    NewtonOptions plain;
    plain.max_iterations = 100;
    const ChordRun newton = run_chord(problem, plain);
    const ChordRun chord = run_chord(problem, chord_options(1));
    INFO(name);
    REQUIRE(chord.iterates.x.size() == newton.iterates.x.size());
    for (std::size_t k = 0; k < chord.iterates.x.size(); ++k) CHECK(chord.iterates.x[k] == newton.iterates.x[k]);
    CHECK(chord.result.status == newton.result.status);
    CHECK(chord.result.factorizations == newton.result.iterations);
    CHECK(chord.result.jacobian_evaluations == newton.result.jacobian_evaluations);
    // Plain Newton's trace says nothing of refactoring.
    for (int flag : newton.iterates.refactored) CHECK(flag == NewtonRecord::every_iteration);
  }
}

TEST_CASE("Chord with K > 1 converges with more iterations and fewer factorizations", "[newton][chord]") {
  struct Expected {
    std::string problem;
    int every, iterations, factorizations;
  };
  // Measured; Newton (K = 1) takes 17 iterations on Powell singular, 4 on Broyden tridiagonal.
  const std::vector<Expected> cases = {{"powell-singular", 1, 17, 17}, {"powell-singular", 2, 24, 12},
                                       {"powell-singular", 5, 38, 8},  {"broyden-tridiagonal", 1, 4, 4},
                                       {"broyden-tridiagonal", 2, 6, 3}, {"broyden-tridiagonal", 5, 8, 2}};
  for (const Expected& expected : cases) {
    INFO(expected.problem << ", K = " << expected.every);
    const TestProblem problem = make_test_problem(expected.problem);
    const ChordRun run = run_chord(problem, chord_options(expected.every));
    REQUIRE(run.result.status == Status::converged);
    Eigen::VectorXd f;
    problem.system->residual(run.result.x, f);
    CHECK(f.lpNorm<Eigen::Infinity>() <= 1e-9);
    CHECK(run.result.iterations == expected.iterations);
    CHECK(run.result.factorizations == expected.factorizations);
    // J is evaluated and factored at iterations 1, K+1, 2K+1, ...: ceil(iterations / K) times.
    CHECK(run.result.factorizations == (run.result.iterations + expected.every - 1) / expected.every);
    CHECK(run.result.jacobian_evaluations == run.result.factorizations);
    for (std::size_t k = 0; k < run.iterates.refactored.size(); ++k) {
      const int flag = expected.every == 1 ? NewtonRecord::every_iteration : int{k % expected.every == 0};
      CHECK(run.iterates.refactored[k] == flag);
    }
  }
}

TEST_CASE("Chord's step between refactorizations solves the old J's system (Eigen's LU)", "[newton][chord]") {
  const TestProblem problem = make_test_problem("broyden-tridiagonal");
  const int every = 3;
  const ChordRun run = run_chord(problem, chord_options(every));
  REQUIRE(run.result.status == Status::converged);
  REQUIRE(run.iterates.x.size() >= 3);
  // Iterations 2 and 3 reuse J(x0): x_k - x_{k-1} solves J(x0) dx = -f(x_{k-1}).
  Eigen::MatrixXd J0;
  problem.system->jacobian(problem.standard_start, J0);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J0);
  for (int k = 1; k < every; ++k) {
    Eigen::VectorXd f;
    problem.system->residual(run.iterates.x[k - 1], f);
    const Eigen::VectorXd expected = lu.solve(-f);
    const Eigen::VectorXd step = run.iterates.x[k] - run.iterates.x[k - 1];
    CHECK((step - expected).lpNorm<Eigen::Infinity>() <= 1e-12 * (1.0 + expected.lpNorm<Eigen::Infinity>()));
  }
}

TEST_CASE("Chord fails with a named status where the old Jacobian points the wrong way", "[newton][chord]") {
  // Newton converges on both (10 and 7 iterations); chord with K = 2 does not.
  const ChordRun helical = run_chord(make_test_problem("helical-valley"), chord_options(2));
  CHECK(helical.result.status == Status::diverged);
  CHECK(helical.result.reason == StopReason::diverged);
  const ChordRun trigonometric = run_chord(make_test_problem("trigonometric"), chord_options(2));
  CHECK(trigonometric.result.status == Status::max_iterations);
  CHECK(trigonometric.result.residual_norm > 1.0);
}

TEST_CASE("Chord is refused with K < 1 and with a linear solver that keeps no factors", "[newton][chord]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  const Dynamic system{*problem.system};
  CHECK_THROWS_AS(DynamicNewton(system, chord_options(0), RuntimeLinearStep("gepp", 2)), std::invalid_argument);
  for (const std::string linear : {"gauss-seidel", "gsl-lu", "eigen-lu", "inverse2x2"}) {
    INFO(linear);
    CHECK_THROWS_AS(DynamicNewton(system, chord_options(2), RuntimeLinearStep(linear, 2)), std::invalid_argument);
    CHECK_NOTHROW(DynamicNewton(system, chord_options(1), RuntimeLinearStep(linear, 2)));
  }
  using SeidelNewton = Newton<Dynamic, linalg::GaussSeidel<Eigen::Dynamic>>;
  CHECK_THROWS_AS(SeidelNewton(system, chord_options(3)), std::invalid_argument);
  // GEPP itself keeps its factors.
  CHECK(Newton<Dynamic>(system, chord_options(3)).solve(problem.standard_start).status == Status::converged);
}
