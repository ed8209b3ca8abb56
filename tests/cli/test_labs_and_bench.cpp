// `numlab labs`, `numlab lab NAME --step` (non-interactive), `numlab bench linear`, and the main job.

#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
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
  for (const std::string lab : {"gauss", "seidel", "inverse2x2"}) {
    const std::string folder = temporary_folder();
    const auto run = run_numlab("lab " + lab + " --step --out " + folder);
    INFO(lab << "\n" << run.err);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("Step 1:") && Contains("Step 3:") && Contains("gsl-lu") && Contains("forward error"));
    // Every table is also saved as CSV; the last one is the comparison with GSL.
    std::vector<std::string> saved;
    for (const auto& entry : std::filesystem::directory_iterator(folder + "/lab-" + lab)) {
      saved.push_back(entry.path().filename().string());
    }
    CHECK(saved.size() >= 2);
    const auto comparison = std::find_if(saved.begin(), saved.end(), [](const std::string& name) {
      return name.ends_with("-comparison.csv");
    });
    REQUIRE(comparison != saved.end());
    std::ifstream csv(folder + "/lab-" + lab + "/" + *comparison);
    std::string header;
    std::getline(csv, header);
    CHECK(header == "method,status,x_1,x_n,relative residual,forward error,time (median)");
    CHECK_THAT(run.out, Contains("(table saved as " + folder + "/lab-" + lab + "/"));
    std::filesystem::remove_all(folder);
  }
  const auto gauss = run_numlab("lab gauss");
  CHECK_THAT(gauss.out, Contains("Wilkinson") && Contains("5.76e+17"));
  const auto seidel = run_numlab("lab seidel");
  CHECK_THAT(seidel.out, Contains("gauss-seidel-plain: diverged") && Contains("gauss-seidel: converged"));
  const auto inverse = run_numlab("lab inverse2x2");
  CHECK_THAT(inverse.out, Contains("singular"));
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
