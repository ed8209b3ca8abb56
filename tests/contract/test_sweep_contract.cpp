// The crank sweeps (Jansen leg, Mustang) against the stepper contract of numlab/solver.hpp: the
// names, status() running between steps and a verdict only after the last, iterations() counting
// poses, x() the last pose solved, and solve() giving what stepping by hand gives.

#include <catch2/catch.hpp>

#include "honesty_checks.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/solver.hpp"

using namespace numlab;
using namespace numlab::mechanisms;

static_assert(Stepper<JansenSweepStepper>);
static_assert(Stepper<MustangSweepStepper>);

namespace {

// Counts the observer's records and checks each against the stepper as it is then.
template <typename Sweep>
class CountingObserver final : public SweepObserver<Sweep> {
 public:
  void on_step(const Sweep& sweep, const SweepPoseRecord& record) override {
    ++attempts;
    if (record.accepted) ++accepted;
    if (!sweep.running()) ++seen_finished;  // an attempt happens inside a step: still running
  }
  int attempts = 0, accepted = 0, seen_finished = 0;
};

}  // namespace

TEST_CASE("Jansen sweep stepper: running between steps, a verdict only at the end", "[contract][sweep]") {
  const auto solver = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", {});
  JansenSweepStepper stepper(JansenModel::eight_equations, *solver);
  CountingObserver<JansenSweepStepper> observer;
  stepper.set_observer(&observer);
  // From 1.57 rad (89.95 deg) the walk-in goes to 0 in its own steps of 5 deg (18 poses: 84.95 ...
  // 4.95, 0), whatever the sweep's step; then 0, 30, 60.
  stepper.start(0.0, 60.0, 30.0);
  CHECK(stepper.running());
  CHECK(stepper.status() == Status::running);
  CHECK(stepper.iterations() == 0);
  int steps = 0;
  while (stepper.step()) {
    ++steps;
    CHECK(stepper.status() == Status::running);
    CHECK(stepper.iterations() == steps);
    REQUIRE(stepper.x().size() == 8);
  }
  ++steps;  // the last step, which returned false
  CHECK_FALSE(stepper.running());
  CHECK(stepper.status() == Status::converged);
  CHECK_FALSE(stepper.step());  // a finished stepper stays finished
  const JansenSweepAngles& result = stepper.result();
  CHECK(result.walk_in_poses == 18);
  CHECK(steps == 1 + 18 + 3);
  CHECK(stepper.iterations() == steps);
  REQUIRE(result.outcomes.size() == 3);
  CHECK(stepper.x() == result.angles.col(2));  // x(): the last pose solved
  CHECK(observer.attempts >= steps);
  CHECK(observer.accepted >= steps);
  CHECK(observer.seen_finished == 0);

  // solve() is start() and step() to the end: the same poses.
  const auto again = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", {});
  const JansenSweepAngles solved = solve_crank_sweep(JansenModel::eight_equations, *again, 0.0, 60.0, 30.0);
  CHECK(solved.angles == result.angles);
  CHECK(solved.status == Status::converged);
  // The same sweep with its checks: converged is justified by the closed form, pose by pose.
  const JansenSweep checked = crank_sweep(JansenModel::eight_equations, *again, 0.0, 60.0, 30.0);
  CHECK(checked.status == Status::converged);
  test::check_justified(checked);
}

TEST_CASE("Jansen sweep stepper: a failure is the verdict of the last step", "[contract][sweep]") {
  nonlinear::NewtonOptions starved;
  starved.max_iterations = 1;  // one Newton step cannot close the leg from the seed's estimates
  const auto solver = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", starved);
  JansenSweepStepper stepper(JansenModel::eight_equations, *solver);
  stepper.start(0.0, 10.0, 5.0);
  while (stepper.step()) CHECK(stepper.status() == Status::running);
  CHECK(stepper.status() == Status::max_iterations);
  CHECK(stepper.result().status == Status::max_iterations);
}

TEST_CASE("Mustang sweep stepper: running between steps, cannot_assemble only at the end", "[contract][sweep]") {
  const auto solver = make_mustang_solver("full", "gepp", {});
  MustangSweepStepper stepper(*solver);
  CountingObserver<MustangSweepStepper> observer;
  stepper.set_observer(&observer);
  stepper.start(50.0, 60.0, 1.0);  // beyond the upper assembly limit near 56.4 deg
  CHECK(stepper.status() == Status::running);
  int steps = 0;
  while (stepper.step()) {
    ++steps;
    CHECK(stepper.status() == Status::running);
    CHECK(stepper.iterations() == steps);
  }
  CHECK(stepper.status() == Status::cannot_assemble);
  CHECK_FALSE(stepper.running());
  const MustangSweep& result = stepper.result();
  CHECK(result.status == Status::cannot_assemble);
  CHECK(result.upper.reached);
  // The seed's start and the poses 50 ... 56 deg.
  CHECK(stepper.iterations() == 1 + static_cast<int>(result.poses.size()));
  CHECK(result.poses.size() == 7);
  CHECK(observer.attempts > observer.accepted);  // the bisection towards the limit failed some solves
  CHECK(observer.seen_finished == 0);
}

TEST_CASE("Mustang sweep stepper: within the range, converged after the last pose", "[contract][sweep]") {
  const auto solver = make_mustang_solver("sequential", "gepp", {});
  MustangSweepStepper stepper(*solver);
  stepper.start(30.0, 50.0, 10.0);  // 45 deg splits it: 50 upwards, then 40, 30 downwards
  int steps = 0;
  while (stepper.step()) {
    ++steps;
    CHECK(stepper.status() == Status::running);
  }
  CHECK(steps + 1 == 4);
  CHECK(stepper.status() == Status::converged);
  test::check_justified(stepper.result());
  REQUIRE(stepper.result().poses.size() == 3);
  CHECK(stepper.result().poses[0].crank_deg == 30.0);
  CHECK(stepper.x() == stepper.result().poses[0].angles);  // the downward march ended at 30 deg
}
