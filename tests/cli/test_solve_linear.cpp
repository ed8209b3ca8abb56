// `numlab solve linear` against docs/cli.md: fields, statuses, exit codes, traces, bad input.

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "run_numlab.hpp"

using numlab::test::run_numlab;
using numlab::test::temporary_file;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using nlohmann::json;

namespace {
json solve_json(const std::string& arguments, int expected_exit) {
  return numlab::test::run_json("solve linear", arguments, expected_exit);
}
}  // namespace
using numlab::test::require_bad_input;

TEST_CASE("solve linear: every method solves a generated system, with the documented JSON fields", "[cli]") {
  for (const std::string method : {"gepp", "gauss-seidel", "gauss-seidel-plain", "gsl-lu", "gsl-qr", "eigen-lu"}) {
    // --max-iter applies to the iterative methods only (docs/cli.md, "Which flags apply where").
    const std::string limit = method.starts_with("gauss-seidel") ? " --max-iter 10000" : "";
    const json out = solve_json("--method " + method + " --generate diag-dominant:6" + limit, 0);
    INFO(method);
    CHECK(out["method"] == method);
    CHECK(out["n"] == 6);
    CHECK(out["status"] == "converged");
    REQUIRE(out["x"].size() == 6);
    for (double value : out["x"]) CHECK(value == Approx(1.0).epsilon(1e-7));
    CHECK(out["relative_residual"].get<double>() < 1e-8);
    CHECK(out["forward_error"].get<double>() < 1e-7);
    CHECK(out["condition_estimate"].get<double>() >= 1.0);
    CHECK(out["time_s"].get<double>() >= 0.0);
    CHECK(out.contains("iterations"));
  }
  const json gepp = solve_json("--method gepp --generate random:5", 0);
  CHECK(gepp["growth_factor"].get<double>() >= 1.0);
  const json closed = solve_json("--method inverse2x2 --generate random:2", 0);
  CHECK(closed["x"][0].get<double>() == Approx(1.0));
}

TEST_CASE("solve linear: method failures exit 1 with the full result", "[cli][failure]") {
  const json singular = solve_json("--method gepp --generate singular:5", 1);
  CHECK(singular["status"] == "singular");
  for (const auto& value : singular["x"]) CHECK(value.is_null());

  const json diverged = solve_json("--method gauss-seidel-plain --generate gs-diverge", 1);
  CHECK(diverged["status"] == "diverged");
  CHECK(diverged["iterations"].get<int>() < 100);

  const json limited = solve_json("--method gauss-seidel --generate hilbert:6 --max-iter 5", 1);
  CHECK(limited["status"] == "max_iterations");
  CHECK(limited["iterations"] == 5);
}

TEST_CASE("solve linear: Wilkinson n = 60 is reported, not hidden", "[cli][wilkinson]") {
  const json out = solve_json("--method gepp --generate wilkinson:60", 0);
  CHECK(out["growth_factor"].get<double>() == std::ldexp(1.0, 59));
  CHECK(out["forward_error"].get<double>() >= 0.5);
  REQUIRE(out["warning"].is_string());
  CHECK_THAT(out["warning"].get<std::string>(), Contains("Growth factor"));
  const auto text = run_numlab("solve linear --method gepp --generate wilkinson:60");
  CHECK_THAT(text.out, Contains("WARNING") && Contains("growth factor      5.765e+17"));
  const json qr = solve_json("--method gsl-qr --generate wilkinson:60", 0);
  CHECK(qr["forward_error"].get<double>() < 1e-10);
  CHECK(qr["warning"].is_null());
}

TEST_CASE("solve linear --trace: the augmented matrix after each swap and elimination", "[cli][trace]") {
  const json out = solve_json("--method gepp --generate gs-diverge --trace", 0);
  const json& trace = out["trace"];
  REQUIRE(trace.size() == 2 + 3 + 3);  // two swaps, three eliminations, three back substitutions
  CHECK(trace[0]["event"] == "row_swap");
  CHECK(trace[0]["swapped_with_row"] == 3);
  CHECK(trace[0]["augmented"][0] == json::array({4.0, 2.0, 1.0, 7.0}));
  CHECK(trace[1]["event"] == "elimination");
  CHECK(trace[1]["augmented"][1][0] == 0.0);
  CHECK(trace[7]["event"] == "back_substitution");
  CHECK(trace[7]["value"].get<double>() == Approx(1.0));

  const auto text = run_numlab("solve linear --method gepp --generate gs-diverge --trace --step");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.err, Contains("swap rows 1 and 3") && Contains("back substitution: x1 = 1"));

  const json sweeps = solve_json("--method gauss-seidel-plain --generate diag-dominant:4 --trace", 0);
  REQUIRE(sweeps["trace"].size() == sweeps["iterations"].get<std::size_t>());
  CHECK(sweeps["trace"][0]["sweep"] == 1);
  CHECK(sweeps["trace"].back()["step_inf"].get<double>() <= 1e-9 * 1.0 + 1e-12);
  CHECK(sweeps["trace"].back().contains("residual_inf"));
  const auto sweep_text = run_numlab("solve linear --method gauss-seidel --generate diag-dominant:4 --trace");
  CHECK_THAT(sweep_text.err, Contains("||dx||_inf") && Contains("||b - A x||_inf"));
}

TEST_CASE("solve linear: matrix files, augmented or with --rhs, and CSV output", "[cli][files]") {
  const std::string square = temporary_file("a.txt", "# A\n4 1\n1 3\n");
  const json ones = solve_json("--method gepp --matrix " + square, 0);
  CHECK(ones["forward_error"].get<double>() < 1e-15);  // b = A * ones
  const std::string augmented = temporary_file("ab.csv", "2,1,-1,8\n-3,-1,2,-11\n-2,1,2,-3\n");
  const json solved = solve_json("--method gepp --matrix " + augmented, 0);
  CHECK(solved["x"][0].get<double>() == Approx(2.0));
  CHECK(solved["x"][1].get<double>() == Approx(3.0));
  CHECK(solved["x"][2].get<double>() == Approx(-1.0));
  CHECK_FALSE(solved.contains("forward_error"));  // no exact solution is known
  const std::string rhs = temporary_file("b.txt", "5\n4\n");
  const json with_rhs = solve_json("--method eigen-lu --matrix " + square + " --rhs " + rhs, 0);
  CHECK(with_rhs["x"][0].get<double>() == Approx(1.0));

  const auto csv = run_numlab("solve linear --method gepp --generate random:3 --format csv");
  CHECK(csv.exit_code == 0);
  CHECK_THAT(csv.out, StartsWith("method,n,status,iterations,relative_residual") && Contains("\ngepp,3,converged,"));
}

TEST_CASE("solve linear: bad input gets one error line and exit 2", "[cli][bad-input]") {
  require_bad_input("solve linear --method lu --generate random:3", "--method");
  require_bad_input("solve linear --method gepp --generate banded:3", "unknown generator 'banded'");
  require_bad_input("solve linear --method gepp --generate random:0", "size 0");
  require_bad_input("solve linear --method gepp --generate random:x", "'x' is not a whole number");
  require_bad_input("solve linear --method gepp --generate random", "expected KIND:N");
  require_bad_input("solve linear --method gepp", "give --generate");
  require_bad_input("solve linear --method gauss-seidel --generate random:3 --tol -1", "--tol: must be a finite number >= 0");
  require_bad_input("solve linear --method inverse2x2 --generate random:3", "inverse2x2 needs a 2x2");
  require_bad_input("solve linear --method gepp --matrix /nonexistent/m.txt", "cannot open");
  require_bad_input("solve linear --method gepp --matrix " + temporary_file("m", "1 2 3\n4 5 6\n7 8 9\n1 1 1\n"),
                    "4x3");
  require_bad_input("solve linear --method gepp --matrix " + temporary_file("m", "1 2\n3 oops\n"), "'oops'");
  require_bad_input("solve linear --method gepp --matrix " + temporary_file("m", "1 2\n3 nan\n"), "not a finite");
  require_bad_input("solve linear --method gepp --matrix " + temporary_file("m", "1 2\n3\n"), "earlier rows have 2");
  const std::string square = temporary_file("a", "4 1\n1 3\n");
  require_bad_input("solve linear --method gepp --matrix " + square + " --rhs " + temporary_file("b", "1 2 3\n"),
                    "3 entries but the matrix has 2 rows");
  require_bad_input("solve linear --method gepp --generate random:3 --matrix " + square, "excludes");
  require_bad_input("solve nonsense", "nonsense");
  require_bad_input("solve", "say what to solve");
}
