// The crank sweeps (Jansen leg, Mustang) and the linkage sweep against the stepper contract of
// numlab/solver.hpp: the names, status() running between steps and a verdict only after the last,
// iterations() counting poses, x() the last pose solved, solve() giving what stepping by hand gives,
// and an observer's stop ending the run without a verdict.

#include <catch2/catch.hpp>

#include "honesty_checks.hpp"
#include <type_traits>

#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/solver.hpp"

using namespace numlab;
using namespace numlab::mechanisms;

static_assert(Stepper<JansenSweepStepper>);
static_assert(Stepper<MustangSweepStepper>);
static_assert(Stepper<LinkageSweepStepper>);
// It keeps a reference to its solver: a temporary is refused.
static_assert(std::is_constructible_v<LinkageSweepStepper, const LinkageSolver&>);
static_assert(!std::is_constructible_v<LinkageSweepStepper, LinkageSolver&&>);

namespace {

// Counts the observer's records and checks each against the stepper as it is then.
template <typename Sweep>
class CountingObserver final : public SweepObserver<Sweep> {
 public:
  StepControl on_step(const Sweep& sweep, const SweepPoseRecord& record) override {
    ++attempts;
    if (record.accepted) ++accepted;
    if (!sweep.running()) ++seen_finished;  // an attempt happens inside a step: still running
    return StepControl::proceed;
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

namespace {

// A four-bar as mechanisms/models/four-bar.toml describes it, with the crank `crank` long: 1.5 (a
// Grashof crank-rocker, it turns fully) or 2.5 (with coupler 2: |AQ| <= 2 + 3.5 only up to a crank
// angle of 99.6 deg, acos(-1/6)).
LinkageModel four_bar(double crank, double coupler) {
  const std::string text = "[linkage]\nname = \"four-bar\"\n[ground]\nO = [0.0, 0.0]\nQ = [4.5, 0.0]\n"
                           "[joints]\nA = [" + std::to_string(crank * 0.5) + ", " + std::to_string(crank * 0.8660254) +
                           "]\nB = [" + (coupler < 3.0 ? "3.0, 3.2" : "4.0, 3.5") + "]\n"
                           "[[link]]\njoints = [\"O\", \"A\"]\nlength = " + std::to_string(crank) + "\n"
                           "[[link]]\njoints = [\"A\", \"B\"]\nlength = " + std::to_string(coupler) + "\n"
                           "[[link]]\njoints = [\"Q\", \"B\"]\nlength = 3.5\n"
                           "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 60.0\n";
  return LinkageModel(parse_linkage_description(text, "four-bar (contract)"));
}

// Checks each pose against the stepper as it is then; stops after `stop_after` poses (0: never).
class PoseObserver final : public StepObserver<LinkageSweepStepper, LinkagePose> {
 public:
  explicit PoseObserver(int stop_after = 0) : stop_after_(stop_after) {}
  StepControl on_step(const LinkageSweepStepper& stepper, const LinkagePose& pose) override {
    ++poses;
    if (!stepper.running()) ++seen_finished;  // a pose is made inside a step: still running
    if (stepper.iterations() != poses || stepper.result().poses.back().driver != pose.driver) ++seen_wrong;
    return poses == stop_after_ ? StepControl::stop : StepControl::proceed;
  }
  int poses = 0, seen_finished = 0, seen_wrong = 0;

 private:
  int stop_after_;
};

// Every converged pose's residual, evaluated again by the model's constraints (not the solver's
// path, fast or generic), within the solver's residual test ||Phi||_inf <= tol (absolute in options()).
void check_residuals(const LinkageSolver& solver, const LinkageSweep& sweep) {
  const LinkageModel& model = solver.model();
  const double tolerance = solver.options().newton.residual_tolerance;
  int converged = 0;
  for (const LinkagePose& pose : sweep.poses) {
    if (pose.outcome.status != Status::converged) continue;
    ++converged;
    Eigen::VectorXd f;
    model.residual(pose.q, model.driver_from_user(pose.driver), f);
    INFO("pose at " << pose.driver << ": ||Phi||_inf " << f.lpNorm<Eigen::Infinity>() << ", tolerance " << tolerance);
    CHECK(f.lpNorm<Eigen::Infinity>() <= tolerance);
  }
  CHECK(converged > 0);
}

}  // namespace

TEST_CASE("linkage sweep stepper: running between steps, a verdict only at the end", "[contract][sweep][linkage]") {
  const LinkageModel model = four_bar(1.5, 4.0);
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    INFO("--solver " << kind);
    const LinkageSolver solver(model, {kind, "gepp", {}});
    LinkageSweepStepper stepper(solver);
    PoseObserver observer;
    stepper.set_observer(&observer);  // the generic path, as --trace
    stepper.start(0.0, 350.0, 10.0);  // the walk from the reference pose at 60 deg to 0 is start()'s
    CHECK(stepper.running());
    CHECK(stepper.status() == Status::running);
    CHECK(stepper.iterations() == 0);
    REQUIRE(stepper.x().size() == 4);  // the walk's pose at the start
    int steps = 0;
    while (stepper.step()) {
      ++steps;
      CHECK(stepper.status() == Status::running);
      CHECK(stepper.iterations() == steps);
      CHECK(stepper.x() == stepper.result().poses.back().q);
    }
    ++steps;  // the last step, which returned false
    CHECK_FALSE(stepper.running());
    CHECK_FALSE(stepper.stopped());
    CHECK(stepper.status() == Status::converged);
    CHECK_FALSE(stepper.step());  // a finished stepper stays finished
    const LinkageSweep& result = stepper.result();
    CHECK(result.status == Status::converged);
    CHECK_FALSE(result.stopped);
    REQUIRE(result.poses.size() == 36);
    CHECK(steps == 36);
    CHECK(stepper.iterations() == 36);
    CHECK(stepper.x() == result.poses.back().q);
    CHECK(observer.poses == 36);
    CHECK(observer.seen_finished == 0);
    CHECK(observer.seen_wrong == 0);
    check_residuals(solver, result);

    // solve() and the free function give what stepping by hand gives, pose for pose.
    const LinkageSweep again = linkage_sweep(solver, 0.0, 350.0, 10.0, [](const LinkagePose&) { return StepControl::proceed; });
    REQUIRE(again.poses.size() == result.poses.size());
    for (std::size_t k = 0; k < again.poses.size(); ++k) CHECK(again.poses[k].q == result.poses[k].q);
    // Without an observer, the fast path where it applies: its poses checked the same way.
    LinkageSweepStepper untraced(solver);
    const LinkageSweep fast = untraced.solve(0.0, 350.0, 10.0);
    CHECK(fast.status == Status::converged);
    CHECK(untraced.iterations() == 36);
    REQUIRE(fast.poses.size() == 36);
    CHECK(untraced.x() == fast.poses.back().q);
    check_residuals(solver, fast);
  }
}

TEST_CASE("linkage sweep stepper: a pose that fails is the verdict only after the last step", "[contract][sweep][linkage]") {
  const LinkageModel model = four_bar(2.5, 2.0);  // assembles up to 99.6 deg
  const LinkageSolver solver(model, {"full", "gepp", {}});
  LinkageSweepStepper stepper(solver);
  stepper.start(60.0, 120.0, 5.0);
  int steps = 0;
  while (stepper.step()) {
    ++steps;
    CHECK(stepper.status() == Status::running);  // the sweep goes on past a failed pose
    CHECK(stepper.iterations() == steps);
  }
  const LinkageSweep& result = stepper.result();
  REQUIRE(result.poses.size() == 13);
  CHECK(stepper.iterations() == 13);
  CHECK(result.poses[7].driver == 95.0);
  CHECK(result.poses[7].outcome.status == Status::converged);
  CHECK(result.poses[8].outcome.status != Status::converged);  // 100 deg and beyond do not assemble
  CHECK(stepper.status() == result.poses[8].outcome.status);
  CHECK(result.status == stepper.status());
  REQUIRE(result.limits.size() == 1);
  CHECK(result.limits[0].driver == Approx(std::acos(-1.0 / 6.0) * 180.0 / std::acos(-1.0)).margin(0.01));
  check_residuals(solver, result);
}

TEST_CASE("linkage sweep stepper: an observer's stop ends the run without a verdict", "[contract][sweep][linkage]") {
  const LinkageModel model = four_bar(1.5, 4.0);
  const LinkageSolver solver(model, {"full", "gepp", {}});
  LinkageSweepStepper stepper(solver);
  PoseObserver observer(3);
  stepper.set_observer(&observer);
  stepper.start(0.0, 90.0, 10.0);
  CHECK(stepper.step());
  CHECK(stepper.step());
  CHECK_FALSE(stepper.step());  // the observer said stop at the third pose
  CHECK(stepper.stopped());
  CHECK_FALSE(stepper.running());
  CHECK(stepper.status() == Status::running);  // no verdict
  CHECK(stepper.iterations() == 3);
  CHECK_FALSE(stepper.step());  // and it stays stopped
  CHECK(stepper.iterations() == 3);
  const LinkageSweep& result = stepper.result();
  CHECK(result.stopped);
  CHECK(result.status == Status::running);
  REQUIRE(result.poses.size() == 3);  // the poses so far
  CHECK(result.poses.back().driver == 20.0);
  CHECK(stepper.x() == result.poses.back().q);
  CHECK(observer.poses == 3);
  check_residuals(solver, result);

  // The free function's std::function observer stops the same way.
  int seen = 0;
  const LinkageSweep stopped = linkage_sweep(solver, 0.0, 90.0, 10.0, [&seen](const LinkagePose&) {
    return ++seen == 3 ? StepControl::stop : StepControl::proceed;
  });
  CHECK(stopped.stopped);
  CHECK(stopped.status == Status::running);
  REQUIRE(stopped.poses.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) CHECK(stopped.poses[k].q == result.poses[k].q);

  // A bad step throws, as the free function does.
  CHECK_THROWS_AS(stepper.start(0.0, 90.0, -10.0), std::invalid_argument);
  CHECK_THROWS_AS(stepper.start(0.0, 90.0, 0.0), std::invalid_argument);
  LinkageSweepStepper never_halving(solver, AtCrossing::smooth, {-1});  // options outside 0 ... 60
  CHECK_THROWS_AS(never_halving.start(0.0, 90.0, 10.0), std::invalid_argument);
}
