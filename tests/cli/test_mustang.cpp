// `numlab mechanism mustang` and `numlab bench mustang` against docs/cli.md: the sweep that
// stops at the assembly limits, exit 1, the range and the loops, the trace, the scenes.

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_numlab.hpp"

using numlab::test::run_json;
using numlab::test::run_numlab;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("mechanism mustang: a wide sweep returns the poses inside the range, the range and its loops, exit 1",
          "[cli][mustang]") {
  const auto out = run_json("mechanism mustang", "--sweep -90:90:0.5", 1);
  CHECK(out["mechanism"] == "mustang");
  CHECK(out["status"] == "cannot_assemble");
  REQUIRE(out["assembly_range_deg"].size() == 2);
  const double lower = out["assembly_range_deg"][0].get<double>(), upper = out["assembly_range_deg"][1].get<double>();
  CHECK(lower == Approx(-41.42).margin(0.02));
  CHECK(upper == Approx(56.45).margin(0.02));
  CHECK(out["limits"]["lower"]["loop"] == 2);
  CHECK(out["limits"]["upper"]["loop"] == 3);
  CHECK(std::abs(out["limits"]["upper"]["failed_deg"].get<double>() - upper) <= 0.01);
  REQUIRE(out["poses"].size() == 195);  // -41, -40.5, ..., 56
  CHECK(out["poses"][0]["crank_deg"] == -41.0);
  CHECK(out["poses"][194]["crank_deg"] == 56.0);
  for (const auto& pose : out["poses"]) {
    CHECK(pose["status"] == "converged");
    CHECK(pose["crank_deg"].get<double>() >= lower);
    CHECK(pose["crank_deg"].get<double>() <= upper);
  }
  CHECK(out["poses"][0]["joints"]["P0"] == nlohmann::json::array({std::sqrt(0.5), 0.0}));
  CHECK(out["poses"][0]["angles"].contains("H"));
  CHECK(out["branch_kept"] == true);
  CHECK(out["worst_closed_form_distance"].get<double>() <= 1e-9);
}

TEST_CASE("mechanism mustang: an angle outside the range is cannot_assemble, exit 1, no pose", "[cli][mustang]") {
  for (const std::string crank : {"80", "-60", "170"}) {
    INFO(crank);
    const auto out = run_json("mechanism mustang", "--crank " + crank, 1);
    CHECK(out["status"] == "cannot_assemble");
    CHECK(out["poses"].empty());
  }
  const auto text = run_numlab("mechanism mustang --crank 80");
  CHECK(text.exit_code == 1);
  CHECK_THAT(text.out, Contains("loop 3 (E, F: quadrilateral 6-7-10-8) cannot close"));
}

TEST_CASE("mechanism mustang: every solver inside the range, exit 0", "[cli][mustang]") {
  for (const std::string solver : {"full", "sequential", "analytic", "gsl-newton", "gsl-hybrids"}) {
    INFO(solver);
    const auto out = run_json("mechanism mustang", "--sweep 0:50:10 --solver " + solver, 0);
    REQUIRE(out["poses"].size() == 6);
    CHECK_FALSE(out.contains("assembly_range_deg"));
    CHECK(out["worst_closed_form_distance"].get<double>() <= 1e-8);
  }
}

TEST_CASE("mechanism mustang --trace: the Jacobian's condition grows towards the limit", "[cli][mustang][trace]") {
  const auto out = run_json("mechanism mustang", "--sweep 50:60:1 --trace", 1);
  REQUIRE(out["trace"].size() > 6);
  double at_start = 0.0, nearest = 0.0, nearest_deg = 0.0;
  for (const auto& attempt : out["trace"]) {
    if (!attempt["accepted"].get<bool>()) continue;
    if (attempt["crank_deg"] == 50.0) at_start = attempt["condition"].get<double>();
    if (attempt["crank_deg"].get<double>() > nearest_deg) {
      nearest_deg = attempt["crank_deg"].get<double>();
      nearest = attempt["condition"].get<double>();
    }
  }
  INFO("kappa " << at_start << " at 50 deg, " << nearest << " at " << nearest_deg << " deg");
  CHECK(nearest > 10.0 * at_start);
  const auto text = run_numlab("mechanism mustang --sweep 50:60:1 --trace");
  CHECK_THAT(text.err, Contains("kappa(J)") && Contains("max_iterations"));
}

TEST_CASE("mechanism mustang CSV: the documented columns", "[cli][mustang]") {
  const auto run = run_numlab("mechanism mustang --sweep 40:50:5 --format csv");
  REQUIRE(run.exit_code == 0);
  std::istringstream lines(run.out);
  std::string header, row;
  std::getline(lines, header);
  CHECK_THAT(header, StartsWith("crank_deg,A,B,C,D,E,F,G,H,x_P0,y_P0,x_P1,y_P1,"));
  CHECK_THAT(header, Contains("x_P12,y_P12,iterations,residual_inf,status"));
  int rows = 0;
  while (std::getline(lines, row)) ++rows;
  CHECK(rows == 3);
}

TEST_CASE("mechanism mustang --svg and --animate: the major links heavier", "[cli][mustang][scene]") {
  const std::string folder = numlab::test::temporary_folder();
  const auto run = run_numlab("mechanism mustang --sweep -90:90:2 --svg " + folder + "/m.svg --animate " + folder + "/ma.svg");
  REQUIRE(run.exit_code == 1);  // the sweep reached both limits; the scenes hold the poses inside
  std::ifstream still(folder + "/m.svg"), moving(folder + "/ma.svg");
  const std::string still_svg((std::istreambuf_iterator<char>(still)), std::istreambuf_iterator<char>());
  const std::string moving_svg((std::istreambuf_iterator<char>(moving)), std::istreambuf_iterator<char>());
  CHECK(still_svg.find("<svg") == 0);
  CHECK_THAT(still_svg, Contains(">P12</text>") && Contains("stroke-width=\"0.220\"") && Contains("stroke-width=\"0.060\""));
  CHECK_THAT(still_svg, Contains("loop 2 stops it") && Contains("loop 3 stops it"));
  CHECK(moving_svg.find("repeatCount=\"indefinite\"") != std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST_CASE("bench mustang: JSON rows as ratios to full Newton", "[cli][bench][mustang]") {
  const auto out = run_json("bench mustang", "--quick", 0);
  REQUIRE(out["rows"].size() == 7);  // full x4 linear solvers, sequential, analytic, gsl-newton
  CHECK(out["rows"][0]["solver"] == "full");
  CHECK(out["rows"][0]["ratio_to_full"] == 1.0);
  for (const auto& row : out["rows"]) {
    INFO(row["solver"]);
    CHECK(row["poses"] == 195);
    CHECK(row["time_s"].get<double>() > 0.0);
    CHECK(row["error"].get<double>() <= 1e-7);
  }
}

TEST_CASE("mechanism mustang: a solver that fails inside the range is not reported as a limit", "[cli][mustang]") {
  const auto out = run_json("mechanism mustang", "--crank 10 --max-iter 1", 1);
  CHECK(out["status"] == "max_iterations");
  CHECK_FALSE(out.contains("assembly_range_deg"));
  CHECK(out["limits"]["lower"]["status"] == "max_iterations");
}
