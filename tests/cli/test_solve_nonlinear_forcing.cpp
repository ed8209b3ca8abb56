// `numlab solve nonlinear --forcing` (inexact Newton) against docs/cli.md: the defect and
// its fix on helical valley with Gauss-Seidel, and the flag refused where it does not apply.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "run_numlab.hpp"

using nlohmann::json;

namespace {
json solve_json(const std::string& arguments, int expected_exit) {
  return numlab::test::run_json("solve nonlinear", arguments, expected_exit);
}
const std::string helical_gs = "--problem helical-valley --method newton --linear gauss-seidel ";
}  // namespace

TEST_CASE("solve nonlinear --forcing: helical valley with Gauss-Seidel converges by default, stalls with none",
          "[cli][nonlinear][forcing]") {
  // The default, Eisenstat-Walker, within the default 20 iterations and tolerance 1e-9.
  const json fixed = solve_json(helical_gs, 0);
  CHECK(fixed["status"] == "converged");
  CHECK(fixed["residual_inf"].get<double>() <= 1e-9);
  CHECK(fixed["distance_to_root"].get<double>() <= 1e-8);  // root (1, 0, 0); J there well conditioned
  const json named = solve_json(helical_gs + "--forcing eisenstat-walker", 0);
  CHECK(named["iterations"] == fixed["iterations"]);
  for (const std::string eta : {"0.5", "0.1", "0.01", "1e-4"}) {
    const json constant = solve_json(helical_gs + "--max-iter 100 --forcing constant:" + eta, 0);
    INFO(eta);
    CHECK(constant["status"] == "converged");
    CHECK(constant["residual_inf"].get<double>() <= 1e-9);
  }
  // The defect, kept on request: Gauss-Seidel's own update test of 1e-9 (exit 1, named).
  const json stalled = solve_json(helical_gs + "--max-iter 200 --forcing none", 1);
  CHECK(stalled["status"] == "max_iterations");
  CHECK(stalled["iterations"] == 200);
  CHECK(stalled["residual_inf"].get<double>() > 1e-9);
}

TEST_CASE("solve nonlinear --forcing: freudenstein-roth with Gauss-Seidel, derailed without a forcing term, converges",
          "[cli][nonlinear][forcing]") {
  // Without one it wanders for 100 iterations (test_solve_nonlinear.cpp); with eta_k it reaches (5, 4).
  const json forced = solve_json("--problem freudenstein-roth --method newton --max-iter 100 --linear gauss-seidel", 0);
  CHECK(forced["status"] == "converged");
  CHECK(forced["residual_inf"].get<double>() <= 1e-9);
  CHECK(forced["distance_to_root"].get<double>() <= 1e-8);
}

TEST_CASE("solve nonlinear --forcing: the trace shows the inner sweeps of every iteration", "[cli][nonlinear][forcing]") {
  const json traced = solve_json(helical_gs + "--trace", 0);
  REQUIRE(traced["trace"].size() == traced["iterations"].get<std::size_t>());
  for (const json& row : traced["trace"]) {
    CHECK(row["linear_status"] == "converged");  // each inner solve reached its eta_k
    CHECK(row["linear_iterations"].get<int>() >= 1);
  }
}

TEST_CASE("solve nonlinear --forcing: refused where it does not apply, and bad values", "[cli][nonlinear][forcing]") {
  using numlab::test::require_bad_input;
  // Direct inner solvers solve exactly; GSL's types have no inner solve of ours.
  require_bad_input("solve nonlinear --problem helical-valley --method newton --forcing none", "--forcing");
  require_bad_input("solve nonlinear --problem helical-valley --method newton --linear eigen-lu --forcing constant:0.1",
                    "--forcing");
  require_bad_input("solve nonlinear --problem helical-valley --method gsl-hybridsj --forcing eisenstat-walker",
                    "--forcing");
  for (const std::string bad : {"sometimes", "constant", "constant:", "constant:1", "constant:0", "constant:-0.5",
                                "constant:nan", "constant:0.1x", "Eisenstat-Walker"}) {
    INFO(bad);
    require_bad_input("solve nonlinear " + helical_gs + "--forcing " + bad, "--forcing");
  }
}
