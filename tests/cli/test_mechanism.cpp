// `numlab mechanism` against docs/cli.md: CSV columns, JSON fields, exit codes, bad input.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "run_numlab.hpp"

using numlab::test::require_bad_input;
using numlab::test::run_json;
using numlab::test::read_all;
using numlab::test::run_numlab;
using numlab::test::temporary_file;
using numlab::test::ProgramRun;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("mechanism jansen: a whole turn, every pose checked against the closed form", "[cli][mechanism]") {
  const auto out = run_json("mechanism jansen", "--sweep 0:359:1 --tol 1e-10", 0);
  CHECK(out["mechanism"] == "jansen");
  CHECK(out["solver"] == "full");
  REQUIRE(out["poses"].size() == 360);
  const auto& pose = out["poses"][90];
  CHECK(pose["crank_deg"] == 90.0);
  CHECK(pose["angles"].size() == 8);
  CHECK(pose["joints"].size() == 8);
  CHECK(pose["joints"]["O"] == nlohmann::json::array({0.0, 0.0}));
  CHECK(pose["joints"]["P1"] == nlohmann::json::array({-38.0, -7.8}));
  CHECK(pose["status"] == "converged");
  CHECK(out["worst_closed_form_distance"].get<double>() <= 1e-8);
  CHECK(out["branch_kept"] == true);
  CHECK(out.contains("time_s"));
}

TEST_CASE("mechanism jansen10 and every solver name", "[cli][mechanism]") {
  for (const std::string solver : {"full", "sequential", "analytic", "gsl-newton", "gsl-hybrids"}) {
    const auto out = run_json("mechanism jansen10", "--sweep 0:90:30 --solver " + solver, 0);
    INFO(solver);
    REQUIRE(out["poses"].size() == 4);
    CHECK(out["poses"][0]["angles"].contains("theta12"));
    CHECK(out["worst_closed_form_distance"].get<double>() <= 1e-8);
  }
}

TEST_CASE("mechanism CSV: one row per crank angle with the documented columns", "[cli][mechanism]") {
  const auto run = run_numlab("mechanism jansen --sweep 0:20:10 --format csv");
  REQUIRE(run.exit_code == 0);
  std::istringstream lines(run.out);
  std::string header, row;
  std::getline(lines, header);
  CHECK_THAT(header, StartsWith("crank_deg,theta1,theta2,theta3,theta4,theta5,theta6,theta7,theta8,x_O,y_O,x_P1,y_P1,"
                                "x_A,y_A,x_B,y_B,x_C,y_C,x_D,y_D,x_E,y_E,x_F,y_F,iterations,residual_inf,status"));
  int rows = 0;
  while (std::getline(lines, row)) ++rows;
  CHECK(rows == 3);
}

TEST_CASE("mechanism: bad input gets one error line and exit 2", "[cli][mechanism][bad-input]") {
  require_bad_input("mechanism strandbeest --crank 10", "name");
  require_bad_input("mechanism jansen", "give --crank DEG, --sweep START:STOP:STEP or --drivers");
  require_bad_input("mechanism jansen --sweep 0:10", "expected START:STOP:STEP");
  require_bad_input("mechanism jansen --sweep 0:10:-1", "point from START to STOP");
  require_bad_input("mechanism jansen --sweep 0:x:1", "'x' is not a finite number");
  require_bad_input("mechanism jansen --crank 10 --sweep 0:10:1", "excludes");
  require_bad_input("mechanism jansen --crank 10 --solver bisection", "--solver");
  require_bad_input("mechanism jansen --crank 10 --tol -1", "--tol: must be a finite number >= 0");
  require_bad_input("mechanism mustang --crank 45 --beest b.svg", "--beest");
  require_bad_input("mechanism mustang --sweep 0:10:-1", "point from START to STOP");
}

TEST_CASE("bench jansen: JSON rows with solver, tolerance, time and error", "[cli][bench][mechanism]") {
  const auto out = run_json("bench jansen", "--quick", 0);
  // full x4 linear solvers, full-std-sin, sequential, sequential-textbook, analytic, gsl-newton, and
  // jansen.toml's derived model by full, sequential and analytic
  REQUIRE(out["rows"].size() == 12);
  CHECK(out["rows"][9]["solver"] == "file-full");
  CHECK(out["rows"][10]["solver"] == "file-sequential");
  CHECK(out["rows"][11]["solver"] == "file-analytic");
  for (const auto& row : out["rows"]) {
    INFO(row["solver"]);
    CHECK(row["tolerance"].get<double>() == 1e-10);
    CHECK(row["time_s"].get<double>() > 0.0);
    CHECK(row["error"].get<double>() <= 1e-8);  // every solver agrees with the closed form
  }
  CHECK(out["rows"][0]["solver"] == "full");
}

TEST_CASE("mechanism --svg and --animate write the scene", "[cli][mechanism][scene]") {
  const std::string folder = numlab::test::temporary_folder();
  const auto run = run_numlab("mechanism jansen --sweep 0:359:10 --svg " + folder + "/leg.svg --animate " + folder +
                              "/leg-animated.svg");
  REQUIRE(run.exit_code == 0);
  std::ifstream still(folder + "/leg.svg"), moving(folder + "/leg-animated.svg");
  const std::string still_svg((std::istreambuf_iterator<char>(still)), std::istreambuf_iterator<char>());
  const std::string moving_svg((std::istreambuf_iterator<char>(moving)), std::istreambuf_iterator<char>());
  CHECK(still_svg.find("<svg") == 0);
  CHECK(still_svg.find(">F</text>") != std::string::npos);  // joints are labelled
  CHECK(still_svg.find("<polygon") != std::string::npos);   // the foot path
  CHECK(moving_svg.find("repeatCount=\"indefinite\"") != std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST_CASE("mechanism jansen --trace: every pose attempt on stderr, or in the JSON", "[cli][mechanism][trace]") {
  // Text: the poses on stdout as without --trace, and one row per attempt on stderr.
  const auto plain = run_numlab("mechanism jansen --sweep 0:10:5");
  const auto traced = run_numlab("mechanism jansen --sweep 0:10:5 --trace");
  REQUIRE(traced.exit_code == 0);
  CHECK(plain.err.empty());
  CHECK_THAT(traced.err, Contains("crank (deg)") && Contains("converged"));
  // From 1.57 rad (89.95 deg) the walk-in reaches 0 deg in steps of 5 deg: 89.95 ... 4.95, then 0,
  // 5 and 10; every one of those attempts is a row, with its crank angle.
  CHECK_THAT(traced.err, Contains("89.95437") && Contains("4.95437") && Contains("10.00000"));

  // JSON: a "trace" array with one entry per attempt, in order, ending at the last pose.
  const auto out = run_json("mechanism jansen", "--sweep 0:10:5 --trace", 0);
  REQUIRE(out.contains("trace"));
  const auto& trace = out["trace"];
  // One solve at the seed's angle, 18 walk-in poses (89.95 -> 4.95 in steps of 5, then 0), and
  // the three requested poses: 22 attempts when none fails (step_halvings 0).
  REQUIRE(out["step_halvings"] == 0);
  CHECK(trace.size() == 1 + 18 + 3);
  for (const auto& attempt : trace) {
    CHECK(attempt.contains("crank_deg"));
    CHECK(attempt.contains("step_deg"));
    CHECK(attempt.contains("iterations"));
    CHECK(attempt.contains("residual_inf"));
    CHECK(attempt["status"] == "converged");
    CHECK(attempt["accepted"] == true);
  }
  CHECK(trace.back()["crank_deg"] == 10.0);
  CHECK(trace.back()["step_deg"] == 5.0);
  CHECK(trace.back()["iterations"] == out["poses"][2]["iterations"]);
  // Without --trace, no "trace".
  CHECK_FALSE(run_json("mechanism jansen", "--sweep 0:10:5", 0).contains("trace"));
}

TEST_CASE("mechanism jansen10 --trace and --step: no terminal, no pause", "[cli][mechanism][trace]") {
  // stdin is not a terminal here, so --step must not wait for Enter.
  const auto run = run_numlab("mechanism jansen10 --sweep 0:10:5 --trace --step");
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.err, Contains("crank (deg)"));
  CHECK_THAT(run.err, !Contains("press Enter"));
  const auto out = run_json("mechanism jansen10", "--sweep 0:10:5 --step", 0);
  CHECK(out["poses"].size() == 3);
}

TEST_CASE("mechanism FILE: the text table shows a micrometre model's coordinates to the same digits as one in metres",
          "[cli][mechanism][scales]") {
  // The shipped four-bar (lengths 1.5 ... 4.5) and the same in micrometres (every length x 1e-6):
  // with a fixed 6 decimals the small one's B showed as 0.000004, one digit of seven.
  const std::string unit = read_all(std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml");
  std::string small = unit;
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"[0.0, 0.0]", "[0.0, 0.0]"}, {"[4.5, 0.0]", "[4.5e-6, 0.0]"}, {"[0.75, 1.3]", "[0.75e-6, 1.3e-6]"},
           {"[4.0, 3.5]", "[4.0e-6, 3.5e-6]"}, {"length = 1.5", "length = 1.5e-6"}, {"length = 4.0", "length = 4.0e-6"},
           {"length = 3.5", "length = 3.5e-6"}}) {
    const auto at = small.find(from);
    REQUIRE(at != std::string::npos);
    small.replace(at, from.size(), to);
  }
  const std::string path = temporary_file("four-bar-um.toml", small);
  const ProgramRun metres = run_numlab("mechanism " + std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml --sweep 0:20:10");
  const ProgramRun micrometres = run_numlab("mechanism " + path + " --sweep 0:20:10");
  REQUIRE(metres.exit_code == 0);
  REQUIRE(micrometres.exit_code == 0);
  // The row at crank 10 deg: B = (3.894721, 3.447265), |v_B| = 1.3907 per radian, in metres; the
  // same digits 1e-6 smaller.
  CHECK_THAT(metres.out, Catch::Matchers::Contains("3.894721  3.447265  1.3907"));
  CHECK_THAT(micrometres.out, Catch::Matchers::Contains("0.000003894721  0.000003447265  0.0000013907"));
}

TEST_CASE("mechanism FILE: a sweep past the boom's stroke names the fold, and its rows show their own residual, no speed",
          "[cli][mechanism]") {
  // The cylinder P-B reaches at most |OP| + |OB| = sqrt(1.17) + 1.5 = 2.5817 m.
  const ProgramRun run = run_numlab("mechanism " + std::string(NUMLAB_MODELS_DIR) + "/hydraulic-boom.toml --sweep 2.5:2.7:0.1");
  CHECK(run.exit_code != 0);
  CHECK_THAT(run.out, Contains("upper limit 2.58 (a fold: the branch ends there"));
  CHECK_THAT(run.out, !Contains("left its branch"));
  std::istringstream lines(run.out);
  std::string line;
  int failed = 0;
  while (std::getline(lines, line)) {
    if (line.find("no_progress") == std::string::npos || line.rfind("  2.", 0) != 0) continue;
    ++failed;
    std::istringstream words(line);
    std::string length, x, y, speed, kappa, iterations, residual;
    words >> length >> x >> y >> speed >> kappa >> iterations >> residual;
    CHECK(speed == "-");
    CHECK(kappa == "-");
    // About the cylinder's shortfall L - 2.5817 (its row, in metres: the other rows hold), never a
    // sub-step's residual near zero; the table prints 3 digits.
    CHECK(std::stod(residual) >= 0.99 * (std::stod(length) - 2.5817));
  }
  CHECK(failed == 2);
}

TEST_CASE("mechanism FILE: velocities are said to be per the driver's own unit, in the text, the JSON and the drawing",
          "[cli][mechanism]") {
  struct Case {
    std::string model, sweep, per;
  };
  const std::string folder = numlab::test::temporary_folder();
  for (const Case& c : {Case{"four-bar", "0:20:10", "radian of crank"}, Case{"hydraulic-boom", "1.4:1.6:0.1", "unit of actuator length"},
                        Case{"slider-crank", "0:20:10", "radian of crank"}, Case{"five-bar", "80:100:10", "radian of crank"}}) {
    INFO(c.model);
    const std::string file = std::string(NUMLAB_MODELS_DIR) + "/" + c.model + ".toml";
    const ProgramRun text = run_numlab("mechanism " + file + " --sweep " + c.sweep);
    REQUIRE(text.exit_code == 0);
    CHECK_THAT(text.out, Contains("velocities per " + c.per));
    CHECK(run_json("mechanism", file + " --sweep " + c.sweep, 0)["links_per"] == c.per);
    const std::string svg = folder + "/" + c.model + ".svg";
    REQUIRE(run_numlab("mechanism " + file + " --sweep " + c.sweep + " --svg " + svg + " --arrows").exit_code == 0);
    const bool two = c.model == "five-bar";
    CHECK_THAT(read_all(svg), Contains("arrows: velocity per " + c.per + (two ? " (the second driver held: partial derivatives)" : ";")));
  }
}
