// numlab bench robustness: one run per case and solver, "solved" exactly when the residual test
// passes, every file written, and the flags it does not take refused.

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "../cli/run_numlab.hpp"

using numlab::test::require_bad_input;
using numlab::test::run_json;

TEST_CASE("numlab bench robustness: every case with every solver, solved only by the residual test", "[cli][bench]") {
  const std::string folder = numlab::test::temporary_folder();
  const auto out = run_json("bench robustness", "--quick --out " + folder, 0);
  CHECK(out["benchmark"] == "robustness");
  const int cases = out["cases"].get<int>();
  REQUIRE(cases > 0);
  const std::size_t solvers = out["solvers"].size();
  REQUIRE(out["runs"].size() == cases * solvers);

  std::set<std::string> names;
  for (const auto& solver : out["solvers"]) names.insert(solver["solver"].get<std::string>());
  for (const std::string type : {"hybrids", "hybrid", "dnewton", "broyden", "hybridsj", "hybridj", "newton", "gnewton"}) {
    CHECK(names.count("gsl-" + type) == 1);
  }
  for (const std::string linear : {"gepp", "gauss-seidel", "gsl-lu", "eigen-lu"}) {
    CHECK(names.count("newton-" + linear) == 1);
    CHECK(names.count("damped-" + linear) == 1);
  }

  for (const auto& run : out["runs"]) {
    INFO(run.dump());
    const std::string solver = run["solver"];
    if (!run["applies"].get<bool>()) {
      CHECK((solver.ends_with("inverse2x2") || solver.starts_with("sequential")));
      continue;
    }
    const bool residual_small = run["residual_inf"].is_number() && run["residual_inf"].get<double>() <= 1e-10;
    CHECK(run["solved"].get<bool>() == residual_small);
    // A solver's "converged" is backed by the residual test (GSL's is on sum |f_i|, stricter).
    if (run["status"] == "converged") CHECK(residual_small);
    CHECK(run["evaluations"].get<double>() >= run["f_evaluations"].get<double>());
    CHECK(run["time_s"].get<double>() > 0.0);
  }
  for (const auto& file : out["files"]) CHECK(std::filesystem::exists(file.get<std::string>()));
  for (const std::string chart : {"robustness-profile-time.svg", "robustness-profile-evaluations.svg", "robustness-data-profile.svg"}) {
    CHECK(std::filesystem::exists(folder + "/" + chart + ".data.csv"));
    CHECK(std::filesystem::exists(folder + "/" + chart + ".gp"));
  }
}

TEST_CASE("numlab bench robustness refuses the flags it does not take", "[cli][bench]") {
  require_bad_input("bench robustness --quick --chart x.svg", "--chart");
  require_bad_input("bench robustness --quick --sizes 2", "--sizes");
  require_bad_input("bench robustness --quick --format csv", "csv");
  require_bad_input("bench robustness --quick --tol 1e-3", "--tol");
}
