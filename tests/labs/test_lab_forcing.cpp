// The newton lab's inexact-Newton step (forcing terms): the trade-off sentence against made-up rows, and
// against the rows the lab itself printed and saved.

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "../cli/run_numlab.hpp"
#include "lab_output.hpp"
#include "lessons/forcing_sentences.hpp"

using Catch::Matchers::Contains;
using numlab::cli::ForcingRun;
using numlab::cli::forcing_tradeoff_sentence;
using numlab::test::column;
using numlab::test::number;

TEST_CASE("The forcing sentence names the fewest outer iterations, the fewest sweeps, and every failure",
          "[labs][sentences][forcing]") {
  const std::vector<ForcingRun> runs = {{"none", "max_iterations", 100, 1859, 4.47e-8},
                                        {"constant:0.5", "converged", 39, 2362, 5.8e-11},
                                        {"constant:0.01", "converged", 10, 2761, 4.5e-12},
                                        {"eisenstat-walker", "converged", 12, 2370, 5.0e-11}};
  const std::string text = forcing_tradeoff_sentence(runs, 1e-10);
  CHECK_THAT(text, Contains("3 of 4 choices converge to ||f||_inf <= 1e-10."));
  CHECK_THAT(text, Contains("The fewest outer iterations: constant:0.01 (10 iterations, 2761 sweeps)"));
  CHECK_THAT(text, Contains("the fewest inner sweeps: constant:0.5 (39 iterations, 2362 sweeps), 1.2x fewer sweeps "
                            "for 29 more iterations."));
  CHECK_THAT(text, Contains("none ends max_iterations after 100 iterations at ||f||_inf = 4.47e-08, above the tolerance."));
  // A "converged" status with a residual above the tolerance is not counted as converged.
  const std::string lying = forcing_tradeoff_sentence({{"constant:0.1", "converged", 5, 50, 1e-3}}, 1e-10);
  CHECK_THAT(lying, Contains("none of the 1 choices converge"));
  CHECK_THAT(lying, Contains("constant:0.1 ends converged after 5 iterations at ||f||_inf = 0.001, above"));
  // One choice best on both counts.
  const std::string both = forcing_tradeoff_sentence({{"a", "converged", 5, 50, 1e-12}, {"b", "converged", 6, 60, 1e-12}}, 1e-10);
  CHECK_THAT(both, Contains("a (5 iterations, 50 sweeps) needs both the fewest outer iterations and the fewest inner sweeps."));
}

TEST_CASE("Newton lab, inexact Newton: each table's sentence is the one its printed rows give", "[labs][forcing]") {
  const numlab::test::LabOutput lab = numlab::test::run_lab("newton");
  REQUIRE(lab.exit_code == 0);
  for (const std::string name : {"forcing-helical-valley", "forcing-jansen"}) {
    const auto table = lab.table("step7-" + name + ".csv");
    REQUIRE(table.size() == 7);  // header, none, four constants, eisenstat-walker
    std::vector<ForcingRun> runs;
    for (std::size_t r = 1; r < table.size(); ++r) {
      const auto& row = table[r];
      runs.push_back({row.at(column(table, "--forcing")), row.at(column(table, "status")),
                      static_cast<int>(number(row.at(column(table, "outer iterations")))),
                      static_cast<int>(number(row.at(column(table, "inner sweeps")))),
                      number(row.at(column(table, "||f||_inf")))});
    }
    INFO(name);
    // The residuals as printed (3 digits) decide "converged" the same way unless one sits at the tolerance.
    CHECK_THAT(lab.text, Contains(forcing_tradeoff_sentence(runs, 1e-10)));
    // The old fixed inner tolerance does not reach 1e-10 on either problem, and says so.
    CHECK(runs.front().forcing == "none");
    CHECK(runs.front().status != "converged");
    // Eisenstat-Walker converges, with the residual test behind it.
    CHECK(runs.back().status == "converged");
    CHECK(runs.back().residual <= 1e-10);
  }
  // Step 5's sentence on Gauss-Seidel inside Newton: its counts are the table's.
  const auto solvers = lab.table("step5-linear-solvers.csv");
  auto cell = [&](std::size_t row, const std::string& header) { return solvers.at(row).at(column(solvers, header)); };
  REQUIRE(cell(1, "--linear") == "gepp");
  REQUIRE(cell(2, "--linear") == "gauss-seidel");
  CHECK_THAT(lab.text, Contains(fmt::format("{} iterations and {} sweeps in all against {} iterations with GEPP's",
                                            cell(2, "iterations"), cell(2, "inner sweeps"), cell(1, "iterations"))));
}
