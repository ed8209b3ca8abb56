// The stepper contract (numlab/solver.hpp) for the dyad's Newton: the names, and status() running
// between steps and converged only after the last one.

#include <catch2/catch.hpp>
#include <cmath>

#include "honesty_checks.hpp"
#include "numlab/mechanisms/dyad_block.hpp"
#include "numlab/mechanisms/dyad_newton.hpp"
#include "numlab/solver.hpp"

using numlab::Status;
using numlab::mechanisms::DyadNewton;

static_assert(numlab::Stepper<DyadNewton>);

TEST_CASE("DyadNewton meets the stepper contract: running between steps and converged only at the end",
          "[contract][dyad]") {
  numlab::nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-13;
  DyadNewton newton(options);
  // Seed 000's first dyad at crank angle 1.57, started a little off its root (a few steps away).
  const double ky = 15.0 * std::sin(1.57) + 7.8, kx = 15.0 * std::cos(1.57) + 38.0;
  newton.set_block(ky, kx, 50.0, 41.5);
  const numlab::mechanisms::DyadBlock block(ky, kx, 50.0, 41.5);  // the same dyad, on std::sin
  newton.start(2.62 + 0.05, 1.40 - 0.05);
  REQUIRE(newton.running());
  CHECK(newton.status() == Status::running);
  CHECK(newton.iterations() == 0);
  CHECK(newton.x() == Eigen::Vector2d(2.62 + 0.05, 1.40 - 0.05));
  int steps = 0;
  while (newton.step()) {
    ++steps;
    INFO("after step " << steps);
    CHECK(newton.running());
    CHECK(newton.status() == Status::running);
    CHECK(newton.x() == Eigen::Vector2d(newton.alpha(), newton.beta()));
  }
  CHECK(steps >= 2);
  CHECK_FALSE(newton.running());
  CHECK(newton.status() == Status::converged);
  CHECK(newton.iterations() == steps + 1);  // the last step is the one that returned false
  CHECK(newton.residual_norm() <= 1e-13);
  // std::sin and the sine table differ by a few ulp: a few eps of the links' lengths.
  numlab::test::check_justified(newton.status(), block, newton.x(), 1e-13 + 1e3 * 2.2e-16 * 50.0);

  // A start already at a root ends in start(): converged with no step.
  const Eigen::Vector2d root = newton.x();
  newton.start(root(0), root(1));
  CHECK_FALSE(newton.running());
  CHECK(newton.status() == Status::converged);
  CHECK(newton.iterations() == 0);
}
