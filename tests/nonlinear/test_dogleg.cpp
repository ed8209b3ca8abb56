// The hand-written trust-region dogleg Newton (numlab/nonlinear/dogleg.hpp): on a linear system it
// is one Newton step; on Rosenbrock it reaches the known root from all three starts; on every
// MINPACK case its "converged" is backed by an independent residual evaluation. The stepper
// Dogleg against the function it replaced (frozen below as reference_dogleg_before_stepper): the
// same x, status, reason, counts and norms, bit for bit, on every MINPACK case and MGH problem
// under five option sets; and what its observer is sent.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"
#include "numlab/nonlinear/minpack_cases.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

namespace {

// f(x) = A x - b.
class LinearSystem final : public DynamicSystem {
 public:
  LinearSystem(Eigen::MatrixXd A, Eigen::VectorXd b) : A_(std::move(A)), b_(std::move(b)) {}
  int dimension() const override { return static_cast<int>(b_.size()); }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const override { f = A_ * x - b_; }
  void jacobian(const Eigen::VectorXd&, Eigen::MatrixXd& J) const override { J = A_; }

 private:
  Eigen::MatrixXd A_;
  Eigen::VectorXd b_;
};

// FROZEN: dogleg_solve as it was before the dogleg became a stepper (nonlinear/.../dogleg.hpp at
// commit 3f34d4a), copied verbatim but for its name and the default argument, and never to be
// edited: the reference that Dogleg and today's dogleg_solve are held to, bit for bit. (At 90
// lines it is longer than the project's 80; it stays as it was, being the record of the old code.)
NewtonResult<Eigen::Dynamic> reference_dogleg_before_stepper(const DynamicSystem& system, const Eigen::VectorXd& x0,
                                                             const NewtonOptions& options) {
  require_tolerance(options.residual_tolerance, "residual tolerance");
  require_tolerance(options.step_tolerance, "step tolerance");
  if (options.max_iterations < 1) throw std::invalid_argument("iteration limit must be at least 1");
  const int n = system.dimension();
  if (x0.size() != n) throw std::invalid_argument("starting point has the wrong number of entries");
  linalg::require_finite(x0, "starting point");
  constexpr double eta = 1e-4;

  NewtonResult<Eigen::Dynamic> result;
  result.x = x0;
  Eigen::VectorXd f(n), trial_f(n);
  Eigen::MatrixXd J(n, n);
  system.residual(result.x, f);
  ++result.function_evaluations;
  double radius = 100.0 * std::max(result.x.norm(), 1.0);  // MINPACK's initial bound, factor 100
  linalg::GaussElimination<Eigen::Dynamic> gepp;
  auto finish = [&](StopReason reason) {
    result.status = status_of(reason);
    result.reason = reason;
    result.residual_norm = f.lpNorm<Eigen::Infinity>();
    return result;
  };
  if (!f.allFinite()) return finish(StopReason::non_finite);
  while (true) {
    if (residual_small(f.lpNorm<Eigen::Infinity>(), options.residual_tolerance)) {
      return finish(StopReason::residual_small);
    }
    if (result.iterations >= options.max_iterations) return finish(StopReason::iteration_limit);
    ++result.iterations;

    // 1. J at x.
    system.jacobian(result.x, J);
    ++result.jacobian_evaluations;
    if (!J.allFinite()) return finish(StopReason::non_finite);

    // 2. The Newton step, when J can be solved.
    const auto newton = gepp.solve(J, -f);
    const bool has_newton = newton.status == Status::converged && newton.x.allFinite();

    // 3. The Cauchy step along g = J^T f.
    const Eigen::VectorXd g = J.transpose() * f;
    const double Jg = (J * g).squaredNorm();
    const Eigen::VectorXd cauchy = Jg > 0.0 ? Eigen::VectorXd(-(g.squaredNorm() / Jg) * g) : Eigen::VectorXd::Zero(n);

    // 4. The dogleg step inside the region.
    Eigen::VectorXd p;
    if (has_newton && newton.x.norm() <= radius) {
      p = newton.x;
    } else if (!has_newton || cauchy.norm() >= radius) {
      if (g.norm() == 0.0) return finish(StopReason::step_small);  // a stationary point of phi
      p = -(radius / g.norm()) * g;
    } else {
      // tau in [0, 1] with ||p_C + tau d|| = radius, d = p_N - p_C: the positive root of a quadratic.
      const Eigen::VectorXd d = newton.x - cauchy;
      const double a = d.squaredNorm(), b = 2.0 * cauchy.dot(d), c = cauchy.squaredNorm() - radius * radius;
      const double tau = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
      p = cauchy + tau * d;
    }

    // 5. Actual against predicted decrease of phi.
    const Eigen::VectorXd trial_x = result.x + p;
    system.residual(trial_x, trial_f);
    ++result.function_evaluations;
    const double phi = 0.5 * f.squaredNorm();
    const double predicted = phi - 0.5 * (f + J * p).squaredNorm();
    const double rho = trial_f.allFinite() && predicted > 0.0 ? (phi - 0.5 * trial_f.squaredNorm()) / predicted
                                                              : -std::numeric_limits<double>::infinity();

    // 6. The radius follows how well the model predicted.
    const double length = p.norm();
    if (rho < 0.25) {
      radius = 0.25 * length;
    } else if (rho > 0.75 && length >= 0.99 * radius) {
      radius = 2.0 * radius;
    }

    // 7. Accept the step when phi decreased enough.
    if (rho > eta) {
      result.x = trial_x;
      f = trial_f;
      result.step_norm = p.lpNorm<Eigen::Infinity>();
    }
    if (step_small(radius, result.x.lpNorm<Eigen::Infinity>(), options.step_tolerance) &&
        !residual_small(f.lpNorm<Eigen::Infinity>(), options.residual_tolerance)) {
      return finish(StopReason::step_small);
    }
  }
}


// Equal to the last bit (NaN included, which == would not call equal).
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (!same_bits(a(i), b(i))) return false;
  }
  return true;
}

void check_identical(const NewtonResult<Eigen::Dynamic>& before, const NewtonResult<Eigen::Dynamic>& now) {
  CHECK(same_bits(before.x, now.x));
  CHECK(before.status == now.status);
  CHECK(before.reason == now.reason);
  CHECK(before.iterations == now.iterations);
  CHECK(before.function_evaluations == now.function_evaluations);
  CHECK(before.jacobian_evaluations == now.jacobian_evaluations);
  CHECK(before.factorizations == now.factorizations);
  CHECK(same_bits(before.residual_norm, now.residual_norm));
  CHECK(same_bits(before.step_norm, now.step_norm));
  CHECK(before.message == now.message);
}

// The option sets the comparison runs under: the robustness lab's budget (residual 1e-10, 100 (n + 1)
// iterations), NewtonOptions' defaults (1e-9, 20), limits of 1 and 3 iterations (runs that end on
// the limit mid-way), and a coarse step tolerance 1e-4 (runs that end as the region collapses).
std::vector<std::pair<std::string, NewtonOptions>> option_sets(int n) {
  NewtonOptions budget;
  budget.residual_tolerance = 1e-10;
  budget.max_iterations = 100 * (n + 1);
  NewtonOptions one = budget, three = budget, coarse = budget;
  one.max_iterations = 1;
  three.max_iterations = 3;
  coarse.step_tolerance = 1e-4;
  return {{"robustness budget", budget}, {"defaults", NewtonOptions{}}, {"limit 1", one}, {"limit 3", three},
          {"step tolerance 1e-4", coarse}};
}

// Passes every step on; counts them.
struct CountingObserver final : Dogleg::Observer {
  int calls = 0;
  StepControl on_step(const Dogleg&, const NewtonRecord&) override {
    ++calls;
    return StepControl::proceed;
  }
};

// The reference, dogleg_solve and a Dogleg stepped by hand with an observer attached, compared.
// Returns the reason the runs ended for.
StopReason compare_on(const DynamicSystem& system, const Eigen::VectorXd& start, const NewtonOptions& options) {
  const auto before = reference_dogleg_before_stepper(system, start, options);
  check_identical(before, dogleg_solve(system, start, options));
  Dogleg stepped(system, options);
  CountingObserver observer;
  stepped.set_observer(&observer);
  stepped.start(start);
  while (stepped.step()) {
  }
  check_identical(before, stepped.result());
  CHECK(stepped.iterations() == before.iterations);
  return before.reason;
}

}  // namespace

TEST_CASE("dogleg on a linear system: the Newton step fits the first region and solves it", "[dogleg]") {
  Eigen::MatrixXd A(3, 3);
  A << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  const Eigen::VectorXd b(Eigen::Vector3d(1, 2, 3));
  const auto result = dogleg_solve(LinearSystem(A, b), Eigen::VectorXd::Zero(3));
  REQUIRE(result.status == Status::converged);
  CHECK(result.iterations == 1);
  const Eigen::VectorXd exact = A.partialPivLu().solve(b);
  const double kappa = A.norm() * A.inverse().norm();
  CHECK((result.x - exact).norm() <= 10 * kappa * std::numeric_limits<double>::epsilon() * exact.norm());
}

TEST_CASE("dogleg reaches Rosenbrock's root (1, 1) from x0, 10 x0 and 100 x0", "[dogleg]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  REQUIRE(problem.known_root.has_value());
  NewtonOptions options;
  options.max_iterations = 300;
  for (double factor : {1.0, 10.0, 100.0}) {
    INFO("start " << factor << " x0");
    const auto result = dogleg_solve(*problem.system, factor * problem.standard_start, options);
    REQUIRE(result.status == Status::converged);
    // J(1, 1) = [[-20, 10], [-1, 0]] is well conditioned: ||x - x*|| is within a few ||f||.
    CHECK((result.x - *problem.known_root).lpNorm<Eigen::Infinity>() <= 100 * options.residual_tolerance);
  }
}

TEST_CASE("dogleg's verdict on every MINPACK case matches the residual at its answer", "[dogleg]") {
  NewtonOptions options;
  options.residual_tolerance = 1e-10;
  for (const MinpackCase& test_case : minpack_cases()) {
    INFO(case_label(test_case));
    const MinpackInstance instance = make_minpack_instance(test_case);
    options.max_iterations = 100 * (test_case.n + 1);
    const auto result = dogleg_solve(*instance.problem.system, instance.start, options);
    Eigen::VectorXd f(test_case.n);
    instance.problem.system->residual(result.x, f);
    const bool root = f.allFinite() && f.lpNorm<Eigen::Infinity>() <= options.residual_tolerance;
    CHECK(root == (result.status == Status::converged));
    CHECK(result.residual_norm == f.lpNorm<Eigen::Infinity>());
    CHECK(result.iterations <= options.max_iterations);
  }
}

TEST_CASE("dogleg refuses a start of the wrong size or not finite", "[dogleg]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  CHECK_THROWS_AS(dogleg_solve(*problem.system, Eigen::VectorXd::Zero(3)), std::invalid_argument);
  CHECK_THROWS_AS(dogleg_solve(*problem.system, Eigen::VectorXd::Constant(2, std::nan(""))), std::invalid_argument);
  Dogleg dogleg(*problem.system);
  CHECK_THROWS_AS(dogleg.start(Eigen::VectorXd::Zero(1)), std::invalid_argument);
  CHECK_THROWS_AS(dogleg.start(Eigen::Vector2d(1.0, std::numeric_limits<double>::infinity())), std::invalid_argument);
}

TEST_CASE("dogleg refuses the options the function before the stepper refused", "[dogleg]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  NewtonOptions negative, infinite, no_iterations;
  negative.residual_tolerance = -1.0;
  infinite.step_tolerance = std::numeric_limits<double>::infinity();
  no_iterations.max_iterations = 0;
  for (const NewtonOptions& options : {negative, infinite, no_iterations}) {
    CHECK_THROWS_AS(reference_dogleg_before_stepper(*problem.system, problem.standard_start, options),
                    std::invalid_argument);
    CHECK_THROWS_AS(Dogleg(*problem.system, options), std::invalid_argument);
    CHECK_THROWS_AS(dogleg_solve(*problem.system, problem.standard_start, options), std::invalid_argument);
  }
}

// The stepper keeps a reference to its system: a temporary is refused at compile time.
static_assert(std::is_constructible_v<Dogleg, const DynamicSystem&, NewtonOptions>);
static_assert(!std::is_constructible_v<Dogleg, const DynamicSystem&&, NewtonOptions>);
static_assert(!std::is_constructible_v<Dogleg, LinearSystem>);

TEST_CASE("the stepper Dogleg gives bit for bit what dogleg_solve gave before it, on every MINPACK case",
          "[dogleg][frozen]") {
  std::map<StopReason, int> reasons;
  int runs = 0;
  for (const MinpackCase& test_case : minpack_cases()) {
    const MinpackInstance instance = make_minpack_instance(test_case);
    for (const auto& [label, options] : option_sets(test_case.n)) {
      INFO(case_label(test_case) << ", " << label);
      ++reasons[compare_on(*instance.problem.system, instance.start, options)];
      ++runs;
    }
  }
  CHECK(runs == 55 * 5);
  // Every ending the comparison is meant to reach, reached.
  CHECK(reasons[StopReason::residual_small] > 0);
  CHECK(reasons[StopReason::step_small] > 0);
  CHECK(reasons[StopReason::iteration_limit] > 0);
}

TEST_CASE("the stepper Dogleg gives bit for bit what dogleg_solve gave before it, on every MGH problem from x0, "
          "10 x0 and 100 x0", "[dogleg][frozen]") {
  int runs = 0;
  for (const std::string& name : test_problem_names()) {
    const TestProblem problem = make_test_problem(name);
    for (double factor : {1.0, 10.0, 100.0}) {
      const Eigen::VectorXd start = minpack_start(name, problem.standard_start, factor);
      for (const auto& [label, options] : option_sets(problem.system->dimension())) {
        INFO(name << " from " << factor << " x0, " << label);
        compare_on(*problem.system, start, options);
        ++runs;
      }
    }
  }
  CHECK(runs == static_cast<int>(test_problem_names().size()) * 3 * 5);
}

TEST_CASE("dogleg's records: x moves by step_norm when accepted (damping 1), not at all when rejected (0)",
          "[dogleg][observer]") {
  // From 100 x0 Rosenbrock's first steps overshoot: rejected steps, the region shrinking, and all
  // three legs of the path.
  const TestProblem problem = make_test_problem("rosenbrock");
  NewtonOptions options;
  options.max_iterations = 300;
  struct Recorder final : Dogleg::Observer {
    Eigen::VectorXd previous_x;
    double previous_radius = 0.0;
    int rejected = 0;
    std::map<DoglegLeg, int> legs;
    StepControl on_step(const Dogleg& dogleg, const NewtonRecord& record) override {
      CHECK(record.iteration == dogleg.iterations());
      CHECK(record.residual_norm == dogleg.residual().lpNorm<Eigen::Infinity>());
      CHECK(record.residual_2norm == dogleg.residual().norm());
      CHECK(dogleg.accepted() == (dogleg.ratio() > Dogleg::eta));
      if (dogleg.accepted()) {
        CHECK(record.damping == 1.0);
        CHECK(dogleg.x() == previous_x + dogleg.trial_step());
        CHECK(record.step_norm == dogleg.trial_step().lpNorm<Eigen::Infinity>());
      } else {
        CHECK(record.damping == 0.0);
        CHECK(dogleg.x() == previous_x);
        CHECK(record.step_norm == 0.0);
      }
      if (dogleg.ratio() < 0.25) CHECK(dogleg.radius() < previous_radius);
      // GEPP's pivot columns: all n when J p_N = -f was solved.
      if (record.linear_status == Status::converged) CHECK(record.linear_iterations == dogleg.residual().size());
      CHECK(std::isnan(record.forcing_term));
      CHECK(record.jacobian_refactored == NewtonRecord::every_iteration);
      rejected += dogleg.accepted() ? 0 : 1;
      ++legs[dogleg.leg()];
      previous_x = dogleg.x();
      previous_radius = dogleg.radius();
      return StepControl::proceed;
    }
  } recorder;
  Dogleg dogleg(*problem.system, options);
  dogleg.set_observer(&recorder);
  const Eigen::VectorXd start = 100.0 * problem.standard_start;
  dogleg.start(start);
  CHECK(std::isnan(dogleg.ratio()));
  CHECK(dogleg.leg() == DoglegLeg::none);
  CHECK(dogleg.radius() == 100.0 * start.norm());  // MINPACK's first radius, 100 max(||x0||_2, 1)
  recorder.previous_x = start;
  recorder.previous_radius = dogleg.radius();
  while (dogleg.step()) {
  }
  CHECK(dogleg.status() == Status::converged);
  CHECK(recorder.rejected > 0);
  CHECK(recorder.legs[DoglegLeg::newton] > 0);
  CHECK(recorder.legs[DoglegLeg::steepest_descent] + recorder.legs[DoglegLeg::dogleg] > 0);
}
