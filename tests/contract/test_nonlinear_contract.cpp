// The stepper contract (numlab/solver.hpp) for the nonlinear steppers: Newton (fixed and dynamic
// sizes), GSL's multiroot adapter, sequential Newton and the trust-region dogleg. The names are checked at compile time;
// at run time, status() is running between steps and gives its verdict only after the last one,
// an observer sees the same, and stepping by hand ends where solve() does.

#include <catch2/catch.hpp>
#include <type_traits>
#include <vector>

#include "../nonlinear/small_systems.hpp"
#include "honesty_checks.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"
#include "numlab/solver.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

namespace {

using DynamicNewton = Newton<DynamicReference, RuntimeLinearStep>;

static_assert(Stepper<Newton<test::FixedRosenbrock>>);
static_assert(Stepper<Newton<test::FixedRosenbrock, linalg::ClosedForm2x2>>);
static_assert(Stepper<DynamicNewton>);
static_assert(Stepper<GslMultiroot>);
static_assert(Stepper<SequentialNewton>);
static_assert(Stepper<Dogleg>);
// The dogleg keeps a reference to its system: a temporary is refused.
static_assert(!std::is_constructible_v<Dogleg, const DynamicSystem&&, NewtonOptions>);

// Steps a started stepper to its end, checking the status rule before and after every step.
// Returns the number of steps taken.
template <typename S>
int step_to_the_end(S& stepper) {
  int steps = 0;
  while (stepper.running()) {
    REQUIRE(stepper.status() == Status::running);
    const bool more = stepper.step();
    ++steps;
    REQUIRE(more == stepper.running());
    if (more) REQUIRE(stepper.status() == Status::running);
  }
  CHECK(stepper.status() != Status::running);
  CHECK_FALSE(stepper.step());  // a finished stepper stays finished
  return steps;
}

// The status each on_step() call saw.
template <typename S, typename Record>
struct StatusLog : StepObserver<S, Record> {
  std::vector<Status> seen;
  StepControl on_step(const S& stepper, const Record&) override { seen.push_back(stepper.status()); return StepControl::proceed; }
};

// Every status an observer saw is running, except the last, which is the stepper's verdict.
template <typename S, typename Record>
void check_observed(const StatusLog<S, Record>& log, Status verdict) {
  REQUIRE_FALSE(log.seen.empty());
  for (std::size_t k = 0; k + 1 < log.seen.size(); ++k) CHECK(log.seen[k] == Status::running);
  CHECK(log.seen.back() == verdict);
}

using test::lab_options;

}  // namespace

TEST_CASE("Fixed-size Newton: running until its last step, converged only after it", "[contract][newton]") {
  const test::FixedRosenbrock rosenbrock;
  Newton<test::FixedRosenbrock> newton(rosenbrock, lab_options());
  StatusLog<Newton<test::FixedRosenbrock>, NewtonRecord> log;
  newton.set_observer(&log);
  newton.start(test::Vector2(-1.2, 1.0));
  CHECK(newton.iterations() == 0);
  const int steps = step_to_the_end(newton);
  CHECK(steps == 2);  // Rosenbrock's second equation is linear: one step fixes x1, the next x2
  CHECK(newton.iterations() == steps);
  CHECK(newton.status() == Status::converged);
  test::check_justified(newton.status(), rosenbrock, newton.x(), lab_options().residual_tolerance);
  CHECK((newton.x() - test::Vector2(1.0, 1.0)).lpNorm<Eigen::Infinity>() <= 1e-15);
  CHECK(log.seen.size() == 2);
  check_observed(log, Status::converged);

  // Started at the root it has nothing to do: finished at once, after no step.
  newton.start(test::Vector2(1.0, 1.0));  // f = 0 exactly
  CHECK_FALSE(newton.running());
  CHECK(newton.status() == Status::converged);
  CHECK(newton.iterations() == 0);
}

TEST_CASE("Dynamic Newton stepped by hand ends where solve() does, on every MGH problem", "[contract][newton][mgh]") {
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    const DynamicReference system{*problem.system};
    DynamicNewton stepped(system, lab_options(), RuntimeLinearStep(LinearMethod::gepp, system.dimension()));
    StatusLog<DynamicNewton, NewtonRecord> log;
    stepped.set_observer(&log);
    stepped.start(problem.standard_start);
    const int steps = step_to_the_end(stepped);
    const auto solved = DynamicNewton(system, lab_options(), RuntimeLinearStep(LinearMethod::gepp, system.dimension()))
                            .solve(problem.standard_start);
    INFO(name << ": " << to_string(solved.status));
    CHECK(stepped.status() == solved.status);
    CHECK(stepped.iterations() == solved.iterations);
    CHECK(steps == solved.iterations);
    CHECK(stepped.x() == solved.x);
    test::check_justified(solved.status, *problem.system, solved.x, lab_options().residual_tolerance);
    // A step that could not move (a singular J) sends no record; every other step sends one.
    if (solved.reason != StopReason::singular_jacobian) check_observed(log, solved.status);
  }
}

TEST_CASE("GSL's adapter stepped by hand ends where solve() does, on every MGH problem", "[contract][gsl][mgh]") {
  for (const std::string type : {"newton", "hybridsj", "broyden"}) {
    for (const std::string& name : test_problem_names()) {
      const TestProblem problem = make_test_problem(name);
      GslMultiroot stepped(*problem.system, type, lab_options());
      StatusLog<GslMultiroot, NewtonRecord> log;
      stepped.set_observer(&log);
      stepped.start(problem.standard_start);
      CHECK(stepped.iterations() == 0);
      const int steps = step_to_the_end(stepped);
      INFO(name << " with " << type << ": " << to_string(stepped.status()));
      check_observed(log, stepped.status());
      const Status stepped_status = stepped.status();
      const Eigen::VectorXd stepped_x = stepped.x();
      // A second start on the same workspace, solved in one call, ends the same way.
      stepped.set_observer(nullptr);
      const auto solved = stepped.solve(problem.standard_start);
      CHECK(solved.status == stepped_status);
      CHECK(solved.iterations == steps);
      CHECK(solved.x == stepped_x);
      test::check_justified(solved.status, *problem.system, solved.x, lab_options().residual_tolerance);
    }
  }
}

TEST_CASE("Sequential Newton: one Newton iteration per step, block after block, converged at the end",
          "[contract][sequential]") {
  // Rosenbrock is block triangular: f2 = 1 - x1 fixes x1, then f1 = 10 (x2 - x1^2) fixes x2. Each
  // block is linear in its own unknown, so one Newton step solves it.
  const TestProblem rosenbrock = make_test_problem("rosenbrock");
  const std::vector<Block> blocks =
      block_triangular_order(jacobian_pattern(*rosenbrock.system, rosenbrock.standard_start));
  REQUIRE(blocks.size() == 2);
  REQUIRE(blocks[0].unknowns == std::vector<int>{0});
  const Eigen::Vector2d start(-1.2, 3.0);
  SequentialNewton stepped(*rosenbrock.system, blocks, {lab_options(), LinearMethod::gepp});

  struct BlockLog : SequentialNewton::Observer {
    std::vector<Status> seen;
    std::vector<int> blocks;
    StepControl on_step(const SequentialNewton& stepper, const SequentialRecord& record) override {
      seen.push_back(stepper.status());
      blocks.push_back(record.block);
      return StepControl::proceed;
    }
  } log;
  stepped.set_observer(&log);
  stepped.start(start);
  CHECK(stepped.x() == start);
  CHECK(stepped.block() == 0);
  CHECK(stepped.step());
  CHECK(stepped.block() == 1);  // the first block converged in its step; the second is under way
  CHECK(stepped.x()(0) == Approx(1.0).epsilon(1e-15));
  CHECK(stepped.x()(1) == 3.0);
  const int steps = 1 + step_to_the_end(stepped);
  CHECK(stepped.status() == Status::converged);
  test::check_justified(stepped.status(), *rosenbrock.system, stepped.x(), lab_options().residual_tolerance);
  CHECK((stepped.x() - Eigen::Vector2d(1.0, 1.0)).lpNorm<Eigen::Infinity>() <= 1e-15);
  CHECK(steps == 2);
  CHECK(stepped.iterations() == steps);
  CHECK(log.blocks == std::vector<int>{0, 1});
  CHECK(log.seen == std::vector<Status>{Status::running, Status::converged});

  const SequentialNewtonResult solved = sequential_newton(*rosenbrock.system, blocks, start, {lab_options()});
  CHECK(solved.status == stepped.status());
  CHECK(solved.iterations == stepped.iterations());
  CHECK(solved.x == stepped.x());
  CHECK(solved.blocks.size() == 2);

  // From the standard start x2 = 1 already solves the second block once x1 = 1: that block ends
  // at its start, with no step, and the solve ends with the first block's step.
  stepped.start(rosenbrock.standard_start);
  CHECK(step_to_the_end(stepped) == 1);
  CHECK(stepped.status() == Status::converged);
  CHECK(stepped.result().blocks.size() == 2);
  CHECK(stepped.result().blocks[1].iterations == 0);
}

TEST_CASE("Dogleg stepped by hand ends where solve() does, on every MGH problem", "[contract][dogleg][mgh]") {
  // What each on_step() call saw: the status, and the record's iteration (checked against iterations()).
  struct Log final : StatusLog<Dogleg, NewtonRecord> {
    std::vector<int> iterations;
    StepControl on_step(const Dogleg& dogleg, const NewtonRecord& record) override {
      iterations.push_back(record.iteration);
      CHECK(record.iteration == dogleg.iterations());
      return StatusLog::on_step(dogleg, record);
    }
  };
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    Dogleg stepped(*problem.system, lab_options());
    Log log;
    stepped.set_observer(&log);
    stepped.start(problem.standard_start);
    CHECK(stepped.iterations() == 0);
    const int steps = step_to_the_end(stepped);
    const auto solved = Dogleg(*problem.system, lab_options()).solve(problem.standard_start);
    INFO(name << ": " << to_string(solved.status) << " (" << to_string(solved.reason) << ")");
    CHECK(stepped.status() == solved.status);
    CHECK(stepped.iterations() == solved.iterations);
    CHECK(steps == solved.iterations);
    CHECK(stepped.x() == solved.x);
    CHECK_FALSE(stepped.stopped());
    test::check_justified(solved.status, *problem.system, solved.x, lab_options().residual_tolerance);
    // Every step sends one record, numbered 1, 2, ...; except a last step that ended before it could
    // move (J not finite, or a stationary point of phi with no Newton step in the region).
    const auto sent = static_cast<int>(log.seen.size());
    for (int k = 0; k < sent; ++k) CHECK(log.iterations[static_cast<std::size_t>(k)] == k + 1);
    if (sent == steps) {
      check_observed(log, solved.status);
    } else {
      CHECK(sent + 1 == steps);
      CHECK((solved.reason == StopReason::non_finite || solved.reason == StopReason::step_small));
      for (const Status seen : log.seen) CHECK(seen == Status::running);
    }
  }
}

TEST_CASE("Dogleg started at a root: converged after no step", "[contract][dogleg]") {
  const TestProblem rosenbrock = make_test_problem("rosenbrock");
  Dogleg dogleg(*rosenbrock.system, lab_options());
  dogleg.start(Eigen::Vector2d(1.0, 1.0));  // f = 0 exactly
  CHECK_FALSE(dogleg.running());
  CHECK(dogleg.status() == Status::converged);
  CHECK(dogleg.iterations() == 0);
  CHECK_FALSE(dogleg.step());
  test::check_justified(dogleg.status(), *rosenbrock.system, dogleg.x(), lab_options().residual_tolerance);
}

TEST_CASE("Dogleg: an observer's stop ends the run at that step, with no verdict", "[contract][dogleg][stop]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  const Eigen::VectorXd start = 10.0 * problem.standard_start;
  const auto full = Dogleg(*problem.system, lab_options()).solve(start);
  REQUIRE(full.status == Status::converged);
  REQUIRE(full.iterations > 3);

  struct StopAt final : Dogleg::Observer {
    int at = 0;
    int calls = 0;
    StepControl on_step(const Dogleg&, const NewtonRecord& record) override {
      ++calls;
      return record.iteration == at ? StepControl::stop : StepControl::proceed;
    }
  } observer;
  observer.at = 3;
  Dogleg dogleg(*problem.system, lab_options());
  dogleg.set_observer(&observer);
  dogleg.start(start);
  CHECK(dogleg.step());
  CHECK(dogleg.step());
  CHECK_FALSE(dogleg.step());  // the observer said stop
  CHECK_FALSE(dogleg.running());
  CHECK(dogleg.stopped());
  CHECK(dogleg.status() == Status::running);  // no verdict: the method did not finish
  CHECK(dogleg.iterations() == 3);
  CHECK_FALSE(dogleg.step());  // and it stays stopped
  CHECK(dogleg.iterations() == 3);
  CHECK(observer.calls == 3);
  const auto stopped = dogleg.result();
  CHECK(stopped.status == Status::running);
  CHECK(stopped.reason == StopReason::running);
  CHECK(stopped.iterations == 3);

  // solve() with the observer attached stops at the same step; a new start clears stopped().
  CHECK(dogleg.solve(start).iterations == 3);
  CHECK(dogleg.stopped());
  dogleg.set_observer(nullptr);
  const auto again = dogleg.solve(start);
  CHECK_FALSE(dogleg.stopped());
  CHECK(again.status == full.status);
  CHECK(again.iterations == full.iterations);
  CHECK(again.x == full.x);

  // A stop sent with the last step changes nothing: the verdict stands.
  observer.at = full.iterations;
  dogleg.set_observer(&observer);
  const auto last = dogleg.solve(start);
  CHECK_FALSE(dogleg.stopped());
  CHECK(last.status == Status::converged);
  CHECK(last.iterations == full.iterations);
}
