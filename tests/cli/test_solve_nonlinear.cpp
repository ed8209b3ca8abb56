// `numlab solve nonlinear` against docs/cli.md: fields, statuses, exit codes, traces, bad input.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "run_numlab.hpp"

using numlab::test::run_numlab;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using nlohmann::json;

namespace {
json solve_json(const std::string& arguments, int expected_exit) {
  return numlab::test::run_json("solve nonlinear", arguments, expected_exit);
}

void require_bad_input(const std::string& arguments, const std::string& named) {
  numlab::test::require_bad_input("solve nonlinear " + arguments, named);
}
}  // namespace

TEST_CASE("solve nonlinear: Newton and every GSL type, with the documented JSON fields", "[cli][nonlinear]") {
  const json newton = solve_json("--problem rosenbrock --method newton", 0);
  CHECK(newton["problem"] == "rosenbrock");
  CHECK(newton["method"] == "newton");
  CHECK(newton["status"] == "converged");
  CHECK(newton["x"][0].get<double>() == Approx(1.0).epsilon(1e-12));
  CHECK(newton["x"][1].get<double>() == Approx(1.0).epsilon(1e-12));
  CHECK(newton["iterations"] == 2);
  CHECK(newton["residual_inf"].get<double>() <= 1e-9);
  CHECK(newton["function_evaluations"].get<int>() >= 3);
  CHECK(newton["jacobian_evaluations"].get<int>() >= 2);
  CHECK(newton["time_s"].get<double>() >= 0.0);
  CHECK(newton["distance_to_root"].get<double>() <= 1e-12);
  CHECK_THAT(newton["termination"].get<std::string>(), StartsWith("Termination: CONVERGED"));
  for (const std::string type : {"hybrids", "hybrid", "dnewton", "broyden", "hybridsj", "hybridj", "newton", "gnewton"}) {
    const json gsl = solve_json("--problem helical-valley --method gsl-" + type + " --max-iter 100", 0);
    INFO(type);
    CHECK(gsl["status"] == "converged");
    CHECK(gsl["distance_to_root"].get<double>() <= 1e-8);
  }
  for (const std::string linear : {"gepp", "gsl-lu", "eigen-lu", "inverse2x2"}) {
    const json run = solve_json("--problem freudenstein-roth --method newton --max-iter 100 --linear " + linear, 0);
    INFO(linear);
    CHECK(run["linear"] == linear);
    CHECK(run["distance_to_root"].get<double>() <= 1e-8);
  }
  // Gauss-Seidel's inexact inner solves without a forcing term (100 sweeps on the normal equations of a
  // nearly singular J) derail Newton on this problem: it wanders for all 100 iterations.
  const json inexact = solve_json(
      "--problem freudenstein-roth --method newton --max-iter 100 --linear gauss-seidel --forcing none", 1);
  CHECK(inexact["status"] == "max_iterations");
  CHECK(inexact["residual_inf"].get<double>() > 1.0);
}

TEST_CASE("solve nonlinear: --x0, --damped and failures exit 1 with the full result", "[cli][nonlinear][failure]") {
  const json from_elsewhere = solve_json("--problem rosenbrock --method newton --x0 2,3", 0);
  CHECK(from_elsewhere["x"][0].get<double>() == Approx(1.0));
  const json trapped = solve_json("--problem freudenstein-roth --method newton --damped --max-iter 100", 1);
  CHECK(trapped["status"] == "no_progress");
  CHECK(trapped["damped"] == true);
  const json limited = solve_json("--problem powell-singular --method newton --max-iter 5", 1);
  CHECK(limited["status"] == "max_iterations");
  CHECK(limited["iterations"] == 5);
  CHECK_THAT(limited["termination"].get<std::string>(), Contains("MAX_ITERATIONS"));
  const json stuck = solve_json("--problem trigonometric --method gsl-hybridsj --max-iter 100 --tol 1e-10", 1);
  CHECK(stuck["status"] == "no_progress");
}

TEST_CASE("solve nonlinear --trace: one row per iteration and the termination line", "[cli][nonlinear][trace]") {
  const json traced = solve_json("--problem wood --method newton --trace", 0);
  const json& trace = traced["trace"];
  REQUIRE(trace.size() == traced["iterations"].get<std::size_t>());
  CHECK(trace[0]["iteration"] == 1);
  CHECK(trace.back()["residual_inf"].get<double>() == Approx(traced["residual_inf"].get<double>()));
  CHECK(trace[0]["linear_status"] == "converged");
  CHECK(trace[0].contains("residual_2"));
  CHECK(trace[0].contains("step_inf"));
  CHECK(trace[0].contains("time_s"));
  const json gsl = solve_json("--problem wood --method gsl-hybridsj --trace --max-iter 100", 0);
  CHECK_FALSE(gsl["trace"][0].contains("linear_status"));  // GSL has no inner solve to report

  const auto text = run_numlab("solve nonlinear --problem rosenbrock --method newton --trace --step");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.err, Contains("||f||_inf") && Contains("linear solve"));
  CHECK_THAT(text.out, Contains("Termination: CONVERGED (residual below tolerance"));
}

TEST_CASE("solve nonlinear --method dogleg: the hand-written trust region, traced like Newton", "[cli][nonlinear][dogleg]") {
  // Powell singular: J is singular at the root, so every method converges linearly (||f|| / 4 per
  // step); the trace has one row per iteration, each an accepted step (lambda 1).
  const json traced = solve_json("--problem powell-singular --method dogleg --trace", 0);
  CHECK(traced["method"] == "dogleg");
  CHECK(traced["status"] == "converged");
  CHECK(traced["residual_inf"].get<double>() <= 1e-9);
  const json& trace = traced["trace"];
  REQUIRE(trace.size() == traced["iterations"].get<std::size_t>());
  for (std::size_t k = 1; k < trace.size(); ++k) {
    CHECK(trace[k]["residual_inf"].get<double>() < trace[k - 1]["residual_inf"].get<double>());
    CHECK(trace[k]["damping"].get<double>() == 1.0);
  }
  CHECK(trace.back()["residual_inf"].get<double>() == Approx(traced["residual_inf"].get<double>()));
  // The options of Newton alone are refused for the dogleg.
  require_bad_input("--problem rosenbrock --method dogleg --damped", "--damped");
  require_bad_input("--problem rosenbrock --method dogleg --linear gauss-seidel", "--linear");
}

TEST_CASE("solve nonlinear: bad input gets one error line and exit 2", "[cli][nonlinear][bad-input]") {
  require_bad_input("--problem beale --method newton", "--problem");
  require_bad_input("--problem wood --method levenberg", "--method");
  require_bad_input("--problem wood --method newton --linear qr", "--linear");
  require_bad_input("--problem wood --method newton --x0 1,2,3", "has 3 numbers but the problem has 4 unknowns");
  require_bad_input("--problem rosenbrock --method newton --x0 1,abc", "'abc' is not a finite number");
  require_bad_input("--problem rosenbrock --method newton --x0 1,nan", "'nan' is not a finite number");
  require_bad_input("--problem rosenbrock --method newton --tol -1", "--tol: must be a finite number >= 0");
  require_bad_input("--problem wood --method newton --linear inverse2x2", "inverse2x2 needs a 2x2");
  // GSL's types do their own step control: --damped would be silently ignored, so it is refused.
  require_bad_input("--problem rosenbrock --method gsl-newton --damped", "--damped applies only to --method newton");
  require_bad_input("--problem wood --method gsl-hybridsj --damped --format json",
                    "--damped applies only to --method newton");
}

TEST_CASE("solve nonlinear: --start and --size pick MINPACK's case, and say so", "[cli][nonlinear][minpack]") {
  // Wood from 10 x0 = (-30, -10, -30, -10): the first trace row's x is not printed, so check the
  // reported start and that the run is the scaled one (its ||f|| at x0 is 1000 times larger).
  const json scaled = solve_json("--problem wood --method newton --damped --start 10 --max-iter 200", 0);
  CHECK(scaled["start"] == "10x0");
  CHECK(scaled["size"] == 4);
  const json chebyquad = solve_json("--problem chebyquad --size 7 --method gsl-hybridsj --max-iter 200", 0);
  CHECK(chebyquad["size"] == 7);
  CHECK(chebyquad["x"].size() == 7);
  CHECK(chebyquad["start"] == "1x0");
  const json given = solve_json("--problem rosenbrock --method newton --x0 2,3", 0);
  CHECK(given["start"] == "given");
  const auto csv = run_numlab("solve nonlinear --problem watson --method newton --start 10 --format csv");
  CHECK_THAT(csv.out, Contains(",size,start,x1,"));
  CHECK_THAT(csv.out, Contains(",6,10x0,"));
  const auto text = run_numlab("solve nonlinear --problem discrete-integral --size 1 --method newton");
  CHECK_THAT(text.out, Contains("n = 1, 1x0"));
}

TEST_CASE("solve nonlinear: a size or start the problem does not have is bad input", "[cli][nonlinear][minpack][failure]") {
  require_bad_input("--problem rosenbrock --method newton --size 3", "--size");
  require_bad_input("--problem watson --method newton --size 32", "--size");
  require_bad_input("--problem chebyquad --method newton --size 0", "--size");
  require_bad_input("--problem broyden-banded --method newton --size 1001", "--size");
  require_bad_input("--problem wood --method newton --start 5", "--start");
  require_bad_input("--problem wood --method newton --start 10 --x0 1,2,3,4", "--start");
}

TEST_CASE("solve nonlinear --reuse-jacobian K: the chord method, traced, counted and refused where it does not apply",
          "[cli][nonlinear][chord]") {
  const json newton = solve_json("--problem powell-singular --method newton", 0);
  CHECK_FALSE(newton.contains("factorizations"));  // plain Newton's output is unchanged
  const json k1 = solve_json("--problem powell-singular --method newton --reuse-jacobian 1", 0);
  CHECK(k1["x"] == newton["x"]);
  CHECK(k1["iterations"] == newton["iterations"]);
  CHECK(k1["factorizations"] == newton["iterations"]);
  const json k5 = solve_json("--problem powell-singular --method newton --reuse-jacobian 5 --max-iter 100 --trace", 0);
  CHECK(k5["status"] == "converged");
  CHECK(k5["reuse_jacobian"] == 5);
  CHECK(k5["iterations"] == 38);  // Newton: 17 iterations and 17 factorizations
  CHECK(k5["factorizations"] == 8);
  CHECK(k5["jacobian_evaluations"] == 8);
  const json& trace = k5["trace"];
  REQUIRE(trace.size() == 38);
  for (std::size_t k = 0; k < trace.size(); ++k) CHECK(trace[k]["jacobian"] == (k % 5 == 0 ? "refactored" : "reused"));
  CHECK_FALSE(newton.contains("trace"));

  // Chord fails where the old J points the wrong way: a named status, exit 1.
  const json helical = solve_json("--problem helical-valley --method newton --reuse-jacobian 2 --max-iter 100", 1);
  CHECK(helical["status"] == "diverged");

  const auto text = run_numlab("solve nonlinear --problem broyden-tridiagonal --method newton --reuse-jacobian 3 --trace");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.err, Contains("refactored") && Contains("reused"));
  CHECK_THAT(text.out, Contains("factorizations     3 (J refactored every 3 iterations)"));

  require_bad_input("--problem rosenbrock --method newton --reuse-jacobian 0", "K must be at least 1");
  require_bad_input("--problem rosenbrock --method newton --reuse-jacobian -2", "K must be at least 1");
  require_bad_input("--problem rosenbrock --method gsl-hybridsj --reuse-jacobian 2",
                    "--reuse-jacobian applies only to --method newton with --linear gepp");
  require_bad_input("--problem rosenbrock --method newton --linear eigen-lu --reuse-jacobian 2",
                    "--reuse-jacobian applies only to --method newton with --linear gepp");
}
