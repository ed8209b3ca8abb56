// The linear methods and the polynomial fit meet the stepper contract (numlab/solver.hpp): the
// names, and a status that is `running` between steps and a verdict only after the last step.

#include <algorithm>
#include <catch2/catch.hpp>
#include <vector>

#include "honesty_checks.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/solver.hpp"

using namespace numlab;
using namespace numlab::linalg;

static_assert(Stepper<GaussElimination<8>>);
static_assert(Stepper<GaussElimination<Eigen::Dynamic>>);
static_assert(Stepper<GaussSeidel<8>>);
static_assert(Stepper<GaussSeidel<Eigen::Dynamic>>);
static_assert(Stepper<ClosedForm2x2>);
static_assert(Stepper<fitting::PolynomialFitter>);

namespace {

// Steps `stepper` (already started) to the end: status() must read `running` while step() says it
// is still running, and give the verdict once step() returns false. Returns the steps taken.
template <typename S>
int steps_with_running_status(S& stepper) {
  CHECK(stepper.running());
  CHECK(stepper.status() == Status::running);
  int steps = 0;
  while (true) {
    const bool more = stepper.step();
    ++steps;
    CHECK(more == stepper.running());
    if (!more) break;
    CHECK(stepper.status() == Status::running);
  }
  CHECK(stepper.status() != Status::running);
  CHECK_FALSE(stepper.step());  // a finished stepper stays finished
  return steps;
}

// Counts the observer's calls.
template <typename S, typename R>
struct CountingObserver : StepObserver<S, R> {
  int calls = 0;
  StepControl on_step(const S&, const R&) override { ++calls; return StepControl::proceed; }
};

}  // namespace

TEST_CASE("GEPP: running through every column and unknown, converged after the last", "[contract][gepp]") {
  const GeneratedSystem system = generate_system("random", 8, 3);
  GaussElimination<8> fixed;
  fixed.start(Matrix<8>(system.A), Vector<8>(system.b));
  CHECK(steps_with_running_status(fixed) == 16);  // 8 pivot columns, 8 unknowns
  CHECK(fixed.status() == Status::converged);
  test::check_justified(fixed.status(), Matrix<8>(system.A), Vector<8>(system.b), fixed.x());
  CHECK(fixed.iterations() == 8);
  CHECK(fixed.x() == fixed.result().x);

  GaussElimination<Eigen::Dynamic> dynamic;
  CountingObserver<GaussElimination<Eigen::Dynamic>, EliminationRecord> observer;
  dynamic.set_observer(&observer);
  dynamic.start(system.A, system.b);
  CHECK(steps_with_running_status(dynamic) == 16);
  CHECK(dynamic.status() == Status::converged);
  test::check_justified(dynamic.status(), system.A, system.b, dynamic.x());
  CHECK(observer.calls >= 16);  // plus one per row swap

  // A singular matrix: the verdict comes at the column whose pivot is negligible.
  Eigen::MatrixXd singular = system.A;
  singular.row(7) = singular.row(0);
  dynamic.start(singular, system.b);
  CHECK(steps_with_running_status(dynamic) <= 8);
  CHECK(dynamic.status() == Status::singular);
}

TEST_CASE("GEPP's iterations() counts pivot columns: k after step k, then n through back substitution",
          "[contract][gepp][iterations]") {
  const GeneratedSystem system = generate_system("random", 3, 5);
  GaussElimination<3> gepp;
  gepp.start(Matrix<3>(system.A), Vector<3>(system.b));
  CHECK(gepp.iterations() == 0);
  int steps = 0;
  while (gepp.running()) {
    gepp.step();
    ++steps;
    INFO("after step " << steps);
    CHECK(gepp.iterations() == std::min(steps, 3));
  }
  CHECK(steps == 6);  // 3 pivot columns, 3 back-substituted unknowns
  CHECK(gepp.status() == Status::converged);
  CHECK(gepp.result().iterations == 3);
  CHECK(GaussElimination<3>().solve(Matrix<3>(system.A), Vector<3>(system.b)).iterations == 3);  // the fast path too
}

TEST_CASE("Gauss-Seidel: running between sweeps, converged only after the last", "[contract][gauss-seidel]") {
  const GeneratedSystem system = generate_system("diag-dominant", 8);
  GaussSeidelOptions options;
  options.system = GaussSeidelOptions::System::plain;
  GaussSeidel<8> fixed(options);
  fixed.start(Matrix<8>(system.A), Vector<8>(system.b));
  const int sweeps = steps_with_running_status(fixed);
  CHECK(sweeps > 1);
  CHECK(fixed.iterations() == sweeps);
  CHECK(fixed.status() == Status::converged);
  test::check_justified(fixed.status(), Matrix<8>(system.A), Vector<8>(system.b), fixed.x(), options.tolerance);

  GaussSeidel<Eigen::Dynamic> dynamic(options);
  CountingObserver<GaussSeidel<Eigen::Dynamic>, SweepRecord> observer;
  dynamic.set_observer(&observer);
  dynamic.start(system.A, system.b);
  CHECK(steps_with_running_status(dynamic) == sweeps);
  CHECK(observer.calls == sweeps);
  CHECK(dynamic.x() == Eigen::VectorXd(fixed.x()));
}

TEST_CASE("The 2x2 closed form: one step, running until it is taken", "[contract][inverse2x2]") {
  Eigen::Matrix2d A;
  A << 4, 3, 6, 3;
  ClosedForm2x2 closed_form;
  CountingObserver<ClosedForm2x2, ClosedFormRecord> observer;
  closed_form.set_observer(&observer);
  closed_form.start(A, Eigen::Vector2d(7, 9));
  CHECK(closed_form.iterations() == 0);
  CHECK(steps_with_running_status(closed_form) == 1);
  CHECK(closed_form.status() == Status::converged);
  test::check_justified(closed_form.status(), A, Eigen::Vector2d(7, 9), closed_form.x());
  CHECK(closed_form.iterations() == 1);
  CHECK(observer.calls == 1);
  CHECK((A * closed_form.x() - Eigen::Vector2d(7, 9)).cwiseAbs().maxCoeff() <= 1e-14);

  Eigen::Matrix2d parallel;
  parallel << 1, 2, 2, 4;
  closed_form.start(parallel, Eigen::Vector2d(1, 2));
  CHECK(steps_with_running_status(closed_form) == 1);
  CHECK(closed_form.status() == Status::singular);
}

TEST_CASE("The polynomial fit: running through its stages, converged after the last", "[contract][fit]") {
  Eigen::VectorXd x(6), y(6);
  x << 0, 1, 2, 3, 4, 5;
  y << 1, 3, 7, 13, 21, 31;  // 1 + x + x^2
  fitting::FitOptions options;
  options.degree = 2;
  for (fitting::FitMethod method : {fitting::FitMethod::normal, fitting::FitMethod::normal_scaled,
                                    fitting::FitMethod::gsl, fitting::FitMethod::eigen_qr}) {
    INFO(to_string(method));
    options.method = method;
    fitting::PolynomialFitter fitter;
    CountingObserver<fitting::PolynomialFitter, fitting::FitRecord> observer;
    fitter.set_observer(&observer);
    fitter.start(x, y, options);
    const bool normal = method == fitting::FitMethod::normal || method == fitting::FitMethod::normal_scaled;
    const int steps = steps_with_running_status(fitter);
    CHECK(steps == (normal ? 3 : 2));  // gsl and eigen-qr have no normal equations to build
    CHECK(observer.calls == steps);
    CHECK(fitter.iterations() == steps);
    CHECK(fitter.status() == Status::converged);
    test::check_justified(fitter.result(), x, y);
    CHECK(fitter.x().size() == 3);
    CHECK(fitter.x() == fitter.result().coefficients);
  }
}
