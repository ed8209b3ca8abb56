// `numlab labs`, `numlab lab NAME --step` (non-interactive), `numlab bench linear`, and the main job.

#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>
#include <nlohmann/json.hpp>
#include <set>

#include "run_numlab.hpp"

using numlab::test::run_numlab;
using numlab::test::temporary_folder;
using Catch::Matchers::Contains;

TEST_CASE("numlab labs lists the labs", "[cli][labs]") {
  const auto run = run_numlab("labs");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("gauss") && Contains("seidel") && Contains("inverse2x2"));
}

TEST_CASE("Each lab runs its steps with --step without blocking, and ends with the GSL comparison", "[cli][labs]") {
  // Each lab's table that compares hand-written methods with GSL, and that table's header.
  const std::map<std::string, std::pair<std::string, std::string>> comparisons = {
      {"gauss", {"step5-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"seidel", {"step4-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"inverse2x2", {"step4-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"newton", {"step3-rosenbrock.csv", "method,status,iterations,||f||_inf,distance,f evals,J evals,time"}}};
  for (const auto& [lab, comparison] : comparisons) {
    const std::string folder = temporary_folder();
    const auto run = run_numlab("lab " + lab + " --step --out " + folder);
    INFO(lab << "\n" << run.err);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("Step 1:") && Contains("Step 3:") && Contains("gsl-"));
    // Every table is also saved as CSV, the GSL comparison among them.
    const std::string saved = folder + "/lab-" + lab + "/" + comparison.first;
    std::ifstream csv(saved);
    REQUIRE(csv.good());
    std::string header;
    std::getline(csv, header);
    CHECK(header == comparison.second);
    CHECK_THAT(run.out, Contains("(table saved as " + saved + ")"));
    std::filesystem::remove_all(folder);
  }
  const auto gauss = run_numlab("lab gauss");
  CHECK_THAT(gauss.out, Contains("Wilkinson") && Contains("5.76e+17"));
  const auto seidel = run_numlab("lab seidel");
  CHECK_THAT(seidel.out, Contains("gauss-seidel-plain: diverged") && Contains("gauss-seidel: converged"));
  const auto inverse = run_numlab("lab inverse2x2");
  CHECK_THAT(inverse.out, Contains("singular"));
  const auto newton = run_numlab("lab newton");
  CHECK_THAT(newton.out, Contains("J(9,10) = -61.6554; AutoDiff -60.0113") && Contains("Step 6:") &&
                             Contains("{theta5, theta8 from eqs 7-8}"));
  const auto unknown = run_numlab("lab nosuchlab");
  CHECK(unknown.exit_code == 2);
}

TEST_CASE("numlab with no arguments runs the main job", "[cli]") {
  const auto run = run_numlab("");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("main job") && Contains("Step 1:"));
}

TEST_CASE("numlab bench linear: JSON rows, a chart, and its data and script beside it", "[cli][bench]") {
  const std::string folder = temporary_folder();
  const auto run = run_numlab("bench linear --quick --sizes 2,8,32 --format json --chart " + folder + "/linear.svg");
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto out = nlohmann::json::parse(run.out);
  std::set<std::string> solvers;
  for (const auto& row : out["rows"]) {
    solvers.insert(row["solver"].get<std::string>());
    CHECK(row["time_s"].get<double>() > 0.0);
    CHECK(row["error"].get<double>() < 1e-6);
    CHECK((row["n"] == 2 || row["n"] == 8 || row["n"] == 32));
  }
  CHECK(solvers == std::set<std::string>{"gepp", "gsl-lu", "eigen-lu", "gauss-seidel", "gauss-seidel-plain"});
  CHECK(out["rows"].size() == 15);
  CHECK(std::filesystem::file_size(folder + "/linear.svg") > 1000);
  CHECK(std::filesystem::exists(folder + "/linear.csv"));
  CHECK(std::filesystem::exists(folder + "/linear.gp"));
  std::filesystem::remove_all(folder);

  const auto bad_chart = run_numlab("bench linear --quick --sizes 2 --chart chart.pdf");
  CHECK(bad_chart.exit_code == 2);
  CHECK_THAT(bad_chart.err, Contains(".svg or .png"));
}
