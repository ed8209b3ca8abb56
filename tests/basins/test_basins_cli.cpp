// `numlab basins` as a user runs it (outputs, formats, bad input), and the lab `basins`: its
// sentences against the numbers of the tables it saved.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/run_numlab.hpp"
#include "../labs/lab_output.hpp"
#include "basins/basin_sentences.hpp"

using Catch::Matchers::Contains;
using numlab::test::column;
using numlab::test::number;
using numlab::test::read_all;
using numlab::test::require_bad_input;
using numlab::test::run_json;
using numlab::test::run_numlab;
using numlab::test::temporary_folder;

namespace {
// The CSV's data lines (the header left out).
int data_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  int lines = -1;
  while (std::getline(in, line)) ++lines;
  return lines;
}

const std::vector<std::string>& row_named(const numlab::test::CsvRows& rows, const std::string& name) {
  for (const auto& row : rows) {
    if (row.at(0) == name) return row;
  }
  FAIL("no row " << name);
  return rows.at(0);
}

int count_in(const numlab::test::CsvRows& rows, const std::string& name, std::size_t column_index) {
  for (const auto& row : rows) {
    if (row.at(0) == name) return static_cast<int>(number(row.at(column_index)));
  }
  return 0;
}
}  // namespace

TEST_CASE("numlab basins draws the chart and writes every start to its CSV", "[basins][cli]") {
  const std::string folder = temporary_folder();
  const auto json = run_json("basins", "fractal --grid 41x31 --threads 2 --out " + folder, 0);
  CHECK(json["columns"] == 41);
  CHECK(json["rows"] == 31);
  int total = 0;
  for (const auto& outcome : json["outcomes"]) total += outcome["count"].get<int>();
  CHECK(total == 41 * 31);
  const std::string chart = folder + "/basins-fractal.png";
  CHECK(std::filesystem::file_size(chart) > 1000);
  CHECK(data_lines(chart + ".data.csv") == 41 * 31);
  CHECK(read_all(chart + ".data.csv").starts_with("i,j,u,v,status,mode,iterations,r,g,b\n"));
  CHECK_THAT(read_all(chart + ".gp"), Contains("rgbimage"));

  const auto text = run_numlab("basins four-bar --grid 21 --chart fb.svg --out " + folder);
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("B+ (left of A->O4)") && Contains("solves per second"));
  CHECK(std::filesystem::exists(folder + "/fb.svg"));
  CHECK_THAT(read_all(folder + "/fb.svg.gp"), Contains("toggle"));

  const auto csv = run_numlab("basins jansen --grid 15 --axes theta2,theta6 --damped --format csv --out " + folder);
  CHECK(csv.exit_code == 0);
  CHECK_THAT(csv.out, Contains("outcome,count,share") && Contains("mode B- C- D+ E-"));
  std::filesystem::remove_all(folder);
}

TEST_CASE("numlab basins refuses bad input with one line, writing nothing", "[basins][cli]") {
  require_bad_input("basins", "system");
  require_bad_input("basins pendulum --out /nonexistent-basins", "unknown system");
  require_bad_input("basins fractal --grid 0", "--grid");
  require_bad_input("basins fractal --grid -5", "--grid");
  require_bad_input("basins fractal --grid 3000", "--grid");
  require_bad_input("basins fractal --grid 10x", "--grid");
  require_bad_input("basins fractal --threads 0", "--threads");
  require_bad_input("basins fractal --u-range 2:1", "--u-range");
  require_bad_input("basins fractal --v-range nan:1", "--v-range");
  require_bad_input("basins fractal --axes theta1,theta2", "--axes");
  require_bad_input("basins jansen --axes theta1,theta9", "theta9");
  require_bad_input("basins jansen --axes theta1,theta1", "differ");
  require_bad_input("basins fractal --tol 1e-3", "--tol");
  require_bad_input("basins fractal --chart x.txt", ".png");
}

TEST_CASE("Lab basins: the sentences say what its tables show", "[basins][lab]") {
  const auto lab = numlab::test::run_lab("basins");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(numlab::test::has_developer_talk(lab.text));
  // Step 1: the fractal's shares, from the table; the origin singular.
  const auto fractal = lab.table("step1-fractal.csv");
  const int total = 201 * 201;
  const std::size_t starts = column(fractal, "starts");
  const int r1 = count_in(fractal, "z = 1", starts), r2 = count_in(fractal, "z = e^{2 pi i/3}", starts),
            r3 = count_in(fractal, "z = e^{-2 pi i/3}", starts);
  CHECK_THAT(lab.text, Contains(numlab::basins::fractal_sentence(r1, r2, r3, total - r1 - r2 - r3, total)));
  CHECK(r2 == r3);  // mirror images under conjugation
  CHECK_THAT(lab.text, Contains("The start at the origin ends singular"));
  // Step 2: the four-bar's shares.
  const auto four_bar = lab.table("step2-four-bar.csv");
  const int plus = count_in(four_bar, "B+ (left of A->O4)", 1), minus = count_in(four_bar, "B- (right of A->O4)", 1);
  const int singular = count_in(four_bar, "singular", 1);
  CHECK_THAT(lab.text, Contains(numlab::basins::four_bar_sentence(plus, minus, singular, total - plus - minus, total)));
  // Step 3: distances and shares, from the saved table.
  const auto d = lab.table("step3-jansen-distances.csv");
  const auto value = [&](const std::string& row, const std::string& which) {
    return number(row_named(d, row).at(column(d, which)));
  };
  const double step = value("grid step (rad)", "plain");
  for (const std::string which : {"plain", "damped"}) {
    const std::string method = which == "plain" ? "Plain Newton" : "Damped Newton";
    CHECK_THAT(lab.text, Contains(numlab::basins::stray_sentence(method, value("nearest start on another branch (rad)", which),
                                                                 value("nearest failing start (rad)", which), step)));
  }
  const int n = static_cast<int>(value("starts", "plain"));
  const int home_plain = static_cast<int>(value("starts reaching the seed's branch", "plain"));
  const int home_damped = static_cast<int>(value("starts reaching the seed's branch", "damped"));
  const int fail_plain = static_cast<int>(value("failing starts", "plain"));
  const int fail_damped = static_cast<int>(value("failing starts", "damped"));
  CHECK(n == 200 * 200);
  CHECK_THAT(lab.text, Contains(numlab::basins::damping_sentence(home_plain, home_damped, n, fail_plain, fail_damped)));
  CHECK_THAT(lab.text, Contains(home_damped > home_plain ? "Damping raises" : "Damping"));
  // The modes table agrees with the distances table.
  const auto modes = lab.table("step3-jansen-modes.csv");
  CHECK(count_in(modes, "B- C- D+ E- (seed's)", column(modes, "plain starts")) == home_plain);
  CHECK(count_in(modes, "B- C- D+ E- (seed's)", column(modes, "damped starts")) == home_damped);
  CHECK_THAT(lab.text, Contains(numlab::basins::seed_position_sentence(
                           value("seed's estimates from the solution (rad)", "plain"), true, "B- C- D+ E-")));
  CHECK(std::filesystem::exists(lab.folder + "/step3-jansen-plain.png"));
}
