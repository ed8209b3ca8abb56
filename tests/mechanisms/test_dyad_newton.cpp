#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/dyad_block.hpp"
#include "numlab/mechanisms/dyad_newton.hpp"
#include "numlab/mechanisms/jansen_sequential.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/newton.hpp"

using numlab::Status;
using numlab::mechanisms::DyadBlock;
using numlab::mechanisms::DyadNewton;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// Seed 000's first dyad at crank angle 1.57: B is where circle(A - P1, l1) meets circle(0, l2),
// seen from P1 (the known part is A - P1 = (li sin 1.57 + a, li cos 1.57 + b) in (y, x) order).
struct FirstDyad {
  double ky = 15.0 * std::sin(1.57) + 7.8, kx = 15.0 * std::cos(1.57) + 38.0, p = 50.0, q = 41.5;
  // The closed form: B - P1 = q u(beta) = k + p u(alpha), on the seed's branch (B to the left of k -> 0).
  Eigen::Vector2d exact() const {
    const Eigen::Vector2d k(kx, ky);  // (x, y)
    const auto B = numlab::mechanisms::circle_intersection(k, p, Eigen::Vector2d::Zero(), q, -1);
    REQUIRE(B.has_value());
    return {std::atan2(B->y() - k.y(), B->x() - k.x()), std::atan2(B->y(), B->x())};
  }
};

numlab::nonlinear::NewtonOptions options_with(double tolerance, int max_iterations = 20) {
  numlab::nonlinear::NewtonOptions options;
  options.residual_tolerance = tolerance;
  options.max_iterations = max_iterations;
  return options;
}

}  // namespace

TEST_CASE("Dyad Newton finds the circle-intersection pose and repeats the generic Newton", "[dyad][reference]") {
  const FirstDyad dyad;
  const Eigen::Vector2d exact = dyad.exact();
  const auto options = options_with(1e-12);
  DyadNewton newton(options);
  newton.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
  for (double offset : {0.2, 0.05, -0.1, 1e-4}) {
    const Eigen::Vector2d start = exact + Eigen::Vector2d(offset, -offset);
    INFO("start offset " << offset);
    REQUIRE(newton.solve(start(0), start(1)) == Status::converged);
    CHECK(newton.residual_norm() <= 1e-12);

    // The angles are within ||J^-1|| times the residual tolerance of the closed form (plus the
    // closed form's own rounding, a few eps times the lengths).
    Eigen::Matrix2d J;
    DyadBlock(dyad.ky, dyad.kx, dyad.p, dyad.q).jacobian(exact, J);
    const double bound = J.inverse().cwiseAbs().rowwise().sum().maxCoeff() * (1e-12 + 100 * eps * dyad.p);
    CHECK(std::abs(newton.alpha() - exact(0)) <= bound);
    CHECK(std::abs(newton.beta() - exact(1)) <= bound);

    // The generic stepper on the same block takes the same steps: same count, same point (to the
    // few ulp by which anchored sines differ from the library's, amplified by ||J^-1||).
    const DyadBlock library(dyad.ky, dyad.kx, dyad.p, dyad.q);
    const auto generic = numlab::nonlinear::newton_solve(library, start, options, numlab::linalg::ClosedForm2x2());
    REQUIRE(generic.status == Status::converged);
    CHECK(newton.iterations() == generic.iterations);
    CHECK(std::abs(newton.alpha() - generic.x(0)) <= bound);
    CHECK(std::abs(newton.beta() - generic.x(1)) <= bound);
  }
}

TEST_CASE("Dyad Newton converges quadratically, one step at a time", "[dyad][stepper]") {
  const FirstDyad dyad;
  const Eigen::Vector2d exact = dyad.exact();
  DyadNewton newton(options_with(1e-13));
  newton.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
  newton.start(exact(0) + 0.05, exact(1) - 0.05);
  REQUIRE(newton.running());
  CHECK(newton.iterations() == 0);
  double previous = newton.residual_norm();
  int steps = 0;
  while (newton.step()) {
    ++steps;
    CHECK(newton.iterations() == steps);
    // Quadratic: each residual is below a modest multiple of the square of the one before.
    CHECK(newton.residual_norm() <= 0.1 * previous * previous + 1e-13);
    previous = newton.residual_norm();
  }
  CHECK(newton.status() == Status::converged);
  CHECK(newton.iterations() <= 5);
  CHECK(!newton.running());
  CHECK_FALSE(newton.step());  // over: further steps do nothing
  // The directions a later block reads are the sines and cosines at the answer.
  CHECK(std::abs(newton.direction(0)(0) - std::sin(newton.alpha())) <= 4 * eps);
  CHECK(std::abs(newton.direction(0)(1) - std::cos(newton.alpha())) <= 4 * eps);
  CHECK(std::abs(newton.direction(1)(0) - std::sin(newton.beta())) <= 4 * eps);
  CHECK(std::abs(newton.direction(1)(1) - std::cos(newton.beta())) <= 4 * eps);
}

TEST_CASE("Dyad Newton placed before its block is known does what solve() does", "[dyad][stepper]") {
  // The sequential solver places every block at its start, then sets each block's known part once
  // the blocks before it are solved: the same iterations and the same point, bit for bit.
  const FirstDyad dyad;
  const Eigen::Vector2d start = dyad.exact() + Eigen::Vector2d(0.03, -0.02);
  DyadNewton whole(options_with(1e-12)), placed(options_with(1e-12));
  whole.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
  REQUIRE(whole.solve(start(0), start(1)) == Status::converged);
  placed.place(start(0), start(1));
  placed.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);  // known only after placing
  REQUIRE(placed.solve_placed() == Status::converged);
  CHECK(placed.iterations() == whole.iterations());
  CHECK(placed.iterations() >= 2);
  CHECK(placed.alpha() == whole.alpha());
  CHECK(placed.beta() == whole.beta());
  CHECK(placed.residual_norm() == whole.residual_norm());
}

TEST_CASE("Dyad Newton's failures: singular Jacobian, a non-finite start, a dyad that cannot close",
          "[dyad][failure]") {
  const FirstDyad dyad;
  SECTION("alpha = beta: the two links are parallel, det J = p q sin(beta - alpha) = 0") {
    DyadNewton newton(options_with(1e-12));
    newton.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
    CHECK(newton.solve(1.0, 1.0) == Status::singular);
    CHECK(newton.iterations() == 1);
    CHECK(newton.alpha() == 1.0);  // the point where the step could not be taken
    CHECK(newton.residual_norm() > 1.0);
  }
  SECTION("a NaN start ends at once, as non_finite") {
    DyadNewton newton(options_with(1e-12));
    newton.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
    CHECK(newton.solve(std::nan(""), 1.0) == Status::non_finite);
    CHECK(newton.iterations() == 0);
  }
  SECTION("|k| > p + q: the circles do not meet, and Newton stops without a pose") {
    DyadNewton newton(options_with(1e-12, 50));
    newton.set_block(0.0, 100.0, dyad.p, dyad.q);  // |k| = 100 > 91.5
    const Status status = newton.solve(0.3, 0.2);
    CHECK(status != Status::converged);
    CHECK(newton.iterations() <= 50);
    CHECK(newton.residual_norm() >= 100.0 - dyad.p - dyad.q - 1e-9);  // the gap cannot be closed
  }
}

namespace {

using numlab::mechanisms::JansenDyad;
using numlab::mechanisms::PoseOutcome;

// A pose solver for the crank sweep that solves every block twice, from the same start and with
// the same known part: by DyadNewton (one per block, kept from pose to pose as the sequential
// solver keeps them; the sweep goes on from its answer) and by Newton<DyadBlock, ClosedForm2x2>.
class BothDyadNewtons final : public numlab::mechanisms::JansenPoseSolver {
 public:
  explicit BothDyadNewtons(const numlab::nonlinear::NewtonOptions& options)
      : options_(options), fast_{DyadNewton(options), DyadNewton(options), DyadNewton(options), DyadNewton(options)} {}

  PoseOutcome solve(double crank_angle, Eigen::VectorXd& theta) override {
    PoseOutcome total;
    const auto dyads = numlab::mechanisms::jansen_dyads();
    for (int b = 0; b < 4; ++b) {
      const JansenDyad& dyad = dyads[static_cast<std::size_t>(b)];
      const Eigen::Vector2d known = numlab::mechanisms::jansen_dyad_known(b, crank_angle, theta);
      const Eigen::Vector2d start(theta(dyad.alpha), theta(dyad.beta));
      DyadNewton& fast = fast_[b];
      fast.set_block(known(0), known(1), dyad.p, dyad.q);
      const Status status = fast.solve(start(0), start(1));
      const DyadBlock block(known(0), known(1), dyad.p, dyad.q);
      const auto textbook = numlab::nonlinear::newton_solve(block, start, options_, numlab::linalg::ClosedForm2x2());

      ++blocks_compared;
      if (status != textbook.status || fast.iterations() != textbook.iterations) {
        ++different_endings;
        UNSCOPED_INFO("crank " << crank_angle << " block " << b << ": " << fast.iterations() << " vs "
                               << textbook.iterations << " iterations");
      }
      // Conditioning: the anchored sines differ from the library's by a few ulp, which moves f by
      // at most a few eps (|k| + p + q) and the root by ||J^-1||_inf times that.
      Eigen::Matrix2d J;
      block.jacobian(textbook.x, J);
      const double amplification = J.inverse().cwiseAbs().rowwise().sum().maxCoeff();
      const double bound = amplification * 8.0 * eps * (known.cwiseAbs().maxCoeff() + dyad.p + dyad.q);
      const double difference = (fast.x() - textbook.x).cwiseAbs().maxCoeff();
      worst_difference = std::max(worst_difference, difference);
      worst_ratio_to_bound = std::max(worst_ratio_to_bound, difference / bound);

      theta(dyad.alpha) = fast.alpha();
      theta(dyad.beta) = fast.beta();
      total.iterations += fast.iterations();
      total.residual_norm = std::max(total.residual_norm, fast.residual_norm());
      if (status != Status::converged) {
        total.status = status;
        return total;
      }
    }
    total.status = Status::converged;
    return total;
  }

  int blocks_compared = 0, different_endings = 0;
  double worst_difference = 0.0, worst_ratio_to_bound = 0.0;

 private:
  numlab::nonlinear::NewtonOptions options_;
  DyadNewton fast_[4];
};

}  // namespace

TEST_CASE("Dyad Newton and the generic Newton on DyadBlock take the same iterations to the same roots in every "
          "block over a crank cycle",
          "[dyad][reference][sweep]") {
  using numlab::mechanisms::JansenModel;
  for (const double tolerance : {1e-6, 1e-10}) {
    BothDyadNewtons both(options_with(tolerance));
    // 360 poses 1 degree apart (and the 18 that walk in from the seed's 1.57 rad), each block
    // warm-started from the sweep's prediction.
    const auto sweep = numlab::mechanisms::solve_crank_sweep(JansenModel::eight_equations, both, 0.0, 359.0, 1.0);
    INFO("tolerance " << tolerance << ": worst difference " << both.worst_difference << ", "
                      << both.worst_ratio_to_bound << " of its bound");
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.outcomes.size() == 360);
    CHECK(both.blocks_compared >= 4 * (360 + 18 + 1));  // 360 poses, 18 walking in, the seed's
    CHECK(both.different_endings == 0);
    CHECK(both.worst_ratio_to_bound <= 1.0);
    CHECK(both.worst_difference > 0.0);  // the anchored sines are in use (the library's would agree exactly)
  }
}

TEST_CASE("The textbook sequential solver (four generic Newtons on DyadBlock) repeats the fast one over a cycle",
          "[dyad][sequential][sweep]") {
  using namespace numlab::mechanisms;
  const auto options = options_with(1e-10);
  TextbookSequentialJansen textbook(options);
  const auto fast = make_jansen_solver(JansenModel::eight_equations, "sequential", "gepp", options);
  const JansenSweep a = crank_sweep(JansenModel::eight_equations, textbook, 0.0, 359.0, 1.0);
  const JansenSweep b = crank_sweep(JansenModel::eight_equations, *fast, 0.0, 359.0, 1.0);
  REQUIRE(a.status == Status::converged);
  REQUIRE(b.status == Status::converged);
  REQUIRE(a.poses.size() == 360);
  REQUIRE(b.poses.size() == 360);
  CHECK(a.worst_closed_form_distance <= 1e-8);
  CHECK(a.orientation_kept);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    INFO("crank " << a.poses[i].crank_deg);
    CHECK(a.poses[i].outcome.iterations == b.poses[i].outcome.iterations);
    worst = std::max(worst, (a.poses[i].angles - b.poses[i].angles).cwiseAbs().maxCoeff());
  }
  CHECK(worst <= 1e-12);  // a few ulp of the sines, amplified by the blocks' conditioning (measured: 4e-15)
}

TEST_CASE("Damping is rejected where it would be ignored: the dyad stepper and the sequential Jansen solver",
          "[dyad][options]") {
  auto damped = options_with(1e-10);
  damped.damped = true;
  CHECK_THROWS_AS(DyadNewton(damped), std::invalid_argument);
  CHECK_THROWS_AS(numlab::mechanisms::make_jansen_solver(numlab::mechanisms::JansenModel::eight_equations, "sequential",
                                                         "gepp", damped),
                  std::invalid_argument);
  // The textbook path honours it (its Newton damps), so it accepts it.
  CHECK_NOTHROW(numlab::mechanisms::TextbookSequentialJansen(damped));
  auto negative = options_with(-1.0);
  CHECK_THROWS_AS(DyadNewton(negative), std::invalid_argument);
  CHECK_NOTHROW(DyadNewton(options_with(1e-10)));
}

TEST_CASE("A small step is not a root: the dyad's and the generic Newton's step test alone gives no_progress",
          "[dyad][honesty]") {
  const FirstDyad dyad;
  const Eigen::Vector2d start = dyad.exact() + Eigen::Vector2d(0.2, -0.2);
  // A step tolerance so loose that the first step passes it, while ||f|| is still far above 1e-12.
  auto loose_step = options_with(1e-12);
  loose_step.step_tolerance = 1e3;
  DyadNewton newton(loose_step);
  newton.set_block(dyad.ky, dyad.kx, dyad.p, dyad.q);
  CHECK(newton.solve(start(0), start(1)) == Status::no_progress);
  CHECK(newton.iterations() == 1);
  CHECK(newton.residual_norm() > 1e-12);
  const DyadBlock library(dyad.ky, dyad.kx, dyad.p, dyad.q);
  const auto generic = numlab::nonlinear::newton_solve(library, start, loose_step, numlab::linalg::ClosedForm2x2());
  CHECK(generic.status == Status::no_progress);
  CHECK(generic.reason == numlab::nonlinear::StopReason::step_small);
  CHECK(generic.iterations == 1);
  // Tolerances that are not finite numbers >= 0 are misuse.
  for (const double bad : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    CHECK_THROWS_AS(DyadNewton(options_with(bad)), std::invalid_argument);
    auto step_bad = options_with(1e-10);
    step_bad.step_tolerance = bad;
    CHECK_THROWS_AS(DyadNewton(step_bad), std::invalid_argument);
  }
}
