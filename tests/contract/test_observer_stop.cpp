// An observer that returns StepControl::stop ends the run at that step (numlab/solver.hpp): step()
// returns false, running() is false, stopped() is true and status() stays running (no verdict), no
// record follows the one that said stop, and the next start() runs afresh. What `--step`'s q relies
// on, for every stepper the program traces. Each case first runs the same problem to its end, so
// that the stop really cut the run short.

#include <catch2/catch.hpp>
#include <vector>

#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"
#include "numlab/solver.hpp"

using namespace numlab;

namespace {

// Says proceed to the first stop_at - 1 records and stop to record stop_at; counts every record.
template <typename S, typename R>
struct StopAt final : StepObserver<S, R> {
  explicit StopAt(int at) : stop_at(at) {}
  StepControl on_step(const S&, const R&) override {
    ++records;
    return records >= stop_at ? StepControl::stop : StepControl::proceed;
  }
  int stop_at;
  int records = 0;
};

// The state the contract promises once the observer has said stop.
template <typename S>
void check_stopped(S& stepper) {
  CHECK(stepper.stopped());
  CHECK_FALSE(stepper.running());
  CHECK(stepper.status() == Status::running);  // no verdict
  CHECK_FALSE(stepper.step());                 // and it stays ended
  CHECK(stepper.stopped());
}

// Runs the stepper (already started by `start`) to its end and returns the records it sent.
template <typename S, typename R, typename Start>
int records_to_the_end(S& stepper, Start start) {
  StopAt<S, R> never(1 << 30);
  stepper.set_observer(&never);
  start();
  while (stepper.step()) {
  }
  CHECK_FALSE(stepper.stopped());
  CHECK(stepper.status() != Status::running);
  stepper.set_observer(nullptr);
  return never.records;
}

// Stops the stepper at record `at` (< the records of a whole run) and checks the contract; then
// starts it again without an observer and checks it reaches a verdict. Returns iterations() as it
// was when the run stopped.
template <typename S, typename R, typename Start>
int check_stop_at(S& stepper, int at, Start start) {
  StopAt<S, R> observer(at);
  stepper.set_observer(&observer);
  start();
  int steps = 0;
  while (stepper.step()) ++steps;
  CHECK(observer.records == at);  // nothing after the record that said stop
  check_stopped(stepper);
  const int iterations_at_stop = stepper.iterations();
  stepper.set_observer(nullptr);
  start();
  CHECK_FALSE(stepper.stopped());
  while (stepper.step()) {
  }
  CHECK(stepper.status() != Status::running);
  return iterations_at_stop;
}

nonlinear::NewtonOptions newton_options() {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-10;
  return options;
}

}  // namespace

TEST_CASE("GEPP stopped by its observer: after a row swap, no elimination follows", "[contract][stop]") {
  using Gepp = linalg::GaussElimination<Eigen::Dynamic>;
  const linalg::GeneratedSystem system = linalg::generate_system("random", 5, 7);
  Gepp gepp;
  const auto start = [&] { gepp.start(system.A, system.b); };
  const int whole = records_to_the_end<Gepp, linalg::EliminationRecord>(gepp, start);
  REQUIRE(whole > 5);
  for (int at : {1, 2, whole - 1}) {
    INFO("stop at record " << at);
    check_stop_at<Gepp, linalg::EliminationRecord>(gepp, at, start);
  }
}

TEST_CASE("Gauss-Seidel stopped by its observer after a sweep", "[contract][stop]") {
  using Seidel = linalg::GaussSeidel<Eigen::Dynamic>;
  const linalg::GeneratedSystem system = linalg::generate_system("diag-dominant", 6, 3);
  Seidel seidel;
  const auto start = [&] { seidel.start(system.A, system.b); };
  const int whole = records_to_the_end<Seidel, linalg::SweepRecord>(seidel, start);
  REQUIRE(whole > 3);
  CHECK(check_stop_at<Seidel, linalg::SweepRecord>(seidel, 2, start) == 2);
}

TEST_CASE("The polynomial fitter stopped by its observer after building the normal equations", "[contract][stop]") {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(8, 0.0, 1.0);
  const Eigen::VectorXd y = x.array().square() + 1.0;
  fitting::FitOptions options;
  options.degree = 2;
  fitting::PolynomialFitter fitter;
  const auto start = [&] { fitter.start(x, y, options); };
  REQUIRE(records_to_the_end<fitting::PolynomialFitter, fitting::FitRecord>(fitter, start) == 3);
  CHECK(check_stop_at<fitting::PolynomialFitter, fitting::FitRecord>(fitter, 1, start) == 1);
}

TEST_CASE("Newton, GSL's adapter and sequential Newton stopped by their observers", "[contract][stop]") {
  using namespace numlab::nonlinear;
  const TestProblem problem = make_test_problem("powell-singular");
  const DynamicReference system{*problem.system};

  using DynamicNewton = Newton<DynamicReference, RuntimeLinearStep>;
  DynamicNewton newton(system, newton_options(), RuntimeLinearStep(LinearMethod::gepp, system.dimension()));
  const auto start_newton = [&] { newton.start(problem.standard_start); };
  REQUIRE(records_to_the_end<DynamicNewton, NewtonRecord>(newton, start_newton) > 3);
  CHECK(check_stop_at<DynamicNewton, NewtonRecord>(newton, 3, start_newton) == 3);

  GslMultiroot gsl(*problem.system, "hybridsj", newton_options());
  const auto start_gsl = [&] { gsl.start(problem.standard_start); };
  REQUIRE(records_to_the_end<GslMultiroot, NewtonRecord>(gsl, start_gsl) > 3);
  CHECK(check_stop_at<GslMultiroot, NewtonRecord>(gsl, 3, start_gsl) == 3);

  const TestProblem rosenbrock = make_test_problem("rosenbrock");
  const std::vector<Block> blocks =
      block_triangular_order(jacobian_pattern(*rosenbrock.system, rosenbrock.standard_start));
  SequentialNewton sequential(*rosenbrock.system, blocks, {newton_options(), LinearMethod::gepp});
  // From (-1.2, 3): one step solves block 0 (x1 = 1), one more block 1 (x2 = 1).
  const auto start_sequential = [&] { sequential.start(Eigen::Vector2d(-1.2, 3.0)); };
  REQUIRE(records_to_the_end<SequentialNewton, SequentialRecord>(sequential, start_sequential) == 2);
  CHECK(check_stop_at<SequentialNewton, SequentialRecord>(sequential, 1, start_sequential) == 1);
}

TEST_CASE("The crank sweeps stopped by their observers: the poses so far, no verdict", "[contract][stop]") {
  using namespace numlab::mechanisms;
  const auto jansen_solver = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", {});
  JansenSweepStepper jansen(JansenModel::eight_equations, *jansen_solver);
  const auto start_jansen = [&] { jansen.start(0.0, 90.0, 10.0); };
  REQUIRE(records_to_the_end<JansenSweepStepper, SweepPoseRecord>(jansen, start_jansen) > 10);
  // Every attempt of this sweep solves at once (no retries): record 4 is pose 4.
  CHECK(check_stop_at<JansenSweepStepper, SweepPoseRecord>(jansen, 4, start_jansen) == 4);

  const auto mustang_solver = make_mustang_solver("full", "gepp", {});
  MustangSweepStepper mustang(*mustang_solver);
  const auto start_mustang = [&] { mustang.start(0.0, 40.0, 5.0); };
  REQUIRE(records_to_the_end<MustangSweepStepper, SweepPoseRecord>(mustang, start_mustang) > 5);
  check_stop_at<MustangSweepStepper, SweepPoseRecord>(mustang, 2, start_mustang);
}
