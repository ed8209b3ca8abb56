// `numlab mechanism FILE --svg` as an engineer asks for it (issue 30 section 4), through the program:
// the pose drawn by default is the one the CSV's condition column makes best, --draw-at's pose has the
// CSV row's coordinates, --path and the file's trace draw exactly the joints named.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "run_numlab.hpp"

using namespace numlab::test;
using Catch::Matchers::Contains;

namespace {

constexpr double printed = 0.0005;  // the SVG's coordinates have three decimals

// A CSV as rows of cells by column name (blank lines skipped).
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  auto cells = [](const std::string& row) {
    std::vector<std::string> out;
    std::string cell;
    std::istringstream split(row);
    while (std::getline(split, cell, ',')) out.push_back(cell);
    if (!row.empty() && row.back() == ',') out.emplace_back();
    return out;
  };
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (header.empty()) {
      header = cells(line);
      continue;
    }
    const auto values = cells(line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size() && k < values.size(); ++k) row[header[k]] = values[k];
    rows.push_back(row);
  }
  return rows;
}

// The centre of joint `name`'s circle, in SVG coordinates (y down).
std::pair<double, double> circle_of(const std::string& svg, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, std::regex("id=\"joint-" + name + "\" cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\"")));
  return {std::stod(m[1]), std::stod(m[2])};
}

// The ids of the drawn paths, in order.
std::vector<std::string> path_ids(const std::string& svg) {
  std::vector<std::string> ids;
  const std::regex path("<path class=\"path\" id=\"path-([A-Za-z0-9_]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it) ids.push_back((*it)[1]);
  return ids;
}

const std::string jansen_joints[] = {"O", "P1", "A", "B", "C", "D", "E", "F"};

}  // namespace

TEST_CASE("mechanism --svg draws the pose whose kappa(J) in the CSV is smallest, --draw-at the CSV row asked for",
          "[cli][mechanism][drawing]") {
  const std::string folder = temporary_folder();
  // jansen.toml is about 100 units across: drawn at 1:1, so the SVG's coordinates are the model's.
  const ProgramRun run = run_numlab("mechanism jansen.toml --sweep 0:350:10 --svg " + folder + "/best.svg --format csv");
  REQUIRE(run.exit_code == 0);
  const auto rows = csv_rows(run.out);
  REQUIRE(rows.size() == 36);
  std::size_t best = rows.size();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k].at("status") != "converged") continue;
    if (best == rows.size() || std::stod(rows[k].at("condition")) < std::stod(rows[best].at("condition"))) best = k;
  }
  REQUIRE(best < rows.size());
  const std::string svg = read_all(folder + "/best.svg");
  CHECK_THAT(svg, Contains("at crank " + rows[best].at("crank_deg") + " deg (the sweep's best-conditioned pose, kappa(J) "));
  for (const std::string& joint : jansen_joints) {
    INFO(joint);
    const auto [x, y] = circle_of(svg, joint);
    CHECK(std::abs(x - std::stod(rows[best].at("x_" + joint))) <= printed);
    CHECK(std::abs(y + std::stod(rows[best].at("y_" + joint))) <= printed);
  }

  // --draw-at 30: the row of crank 30, whichever pose is best.
  const ProgramRun at = run_numlab("mechanism jansen.toml --sweep 0:350:10 --draw-at 30 --svg " + folder + "/at.svg --format csv");
  REQUIRE(at.exit_code == 0);
  const auto row = csv_rows(at.out)[3];
  REQUIRE(row.at("crank_deg") == "30");
  const std::string drawn = read_all(folder + "/at.svg");
  CHECK_THAT(drawn, Contains("at crank 30 deg (--draw-at)"));
  for (const std::string& joint : jansen_joints) {
    INFO(joint);
    const auto [x, y] = circle_of(drawn, joint);
    CHECK(std::abs(x - std::stod(row.at("x_" + joint))) <= printed);
    CHECK(std::abs(y + std::stod(row.at("y_" + joint))) <= printed);
  }
  std::filesystem::remove_all(folder);
}

TEST_CASE("mechanism --draw-at outside the sweep's poses, or where it does not assemble, is bad input", "[cli][mechanism][drawing]") {
  const std::string folder = temporary_folder();
  require_bad_input("mechanism four-bar --sweep 0:350:10 --draw-at 35 --svg " + folder + "/x.svg",
                    "--draw-at 35: not a pose of the sweep, whose poses run from 0 to 350 in steps of 10");
  // The Mustang's file assembles from -41.4 to 56.5 degrees.
  require_bad_input("mechanism mustang.toml --sweep 0:90:10 --draw-at 80 --svg " + folder + "/x.svg",
                    "--draw-at 80: the linkage did not assemble there");
  require_bad_input("mechanism four-bar --sweep 0:350:10 --draw-at 30", "--draw-at applies only to --svg FILE");
  CHECK(std::filesystem::is_empty(folder));
  std::filesystem::remove_all(folder);
}

TEST_CASE("mechanism --path and the file's trace draw exactly the joints named", "[cli][mechanism][drawing]") {
  const std::string folder = temporary_folder();
  // Every moving joint's path without a choice; --path A,F (or --path A --path F) only those two.
  REQUIRE(run_numlab("mechanism jansen.toml --sweep 0:350:10 --svg " + folder + "/all.svg").exit_code == 0);
  CHECK(path_ids(read_all(folder + "/all.svg")).size() == 6);
  REQUIRE(run_numlab("mechanism jansen.toml --sweep 0:350:10 --path A,F --svg " + folder + "/two.svg").exit_code == 0);
  CHECK(path_ids(read_all(folder + "/two.svg")) == std::vector<std::string>{"A", "F"});
  REQUIRE(run_numlab("mechanism jansen.toml --sweep 0:350:10 --path F --path A --animate " + folder + "/two-animated.svg").exit_code == 0);
  CHECK(path_ids(read_all(folder + "/two-animated.svg")) == std::vector<std::string>{"F", "A"});
  // The file's trace, unless --path says otherwise.
  std::string text = read_all(std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml");
  text.replace(text.find("[ground]"), 8, "trace = [\"B\"]\n\n[ground]");
  const std::string file = folder + "/traced.toml";
  std::ofstream(file) << text;
  REQUIRE(run_numlab("mechanism " + file + " --sweep 0:350:10 --svg " + folder + "/traced.svg").exit_code == 0);
  const std::string traced = read_all(folder + "/traced.svg");
  CHECK(path_ids(traced) == std::vector<std::string>{"B"});
  CHECK_THAT(traced, Contains("the path of B over 36 assembled poses (the file's trace)"));
  REQUIRE(run_numlab("mechanism " + file + " --sweep 0:350:10 --path A --svg " + folder + "/chosen.svg").exit_code == 0);
  CHECK(path_ids(read_all(folder + "/chosen.svg")) == std::vector<std::string>{"A"});
  require_bad_input("mechanism " + file + " --sweep 0:350:10 --path Z --svg " + folder + "/x.svg",
                    "--path 'Z': not a joint of four-bar; name a moving joint (A, B)");
  require_bad_input("mechanism " + file + " --sweep 0:350:10 --path Q --svg " + folder + "/x.svg",
                    "--path Q: a ground joint has no path; name a moving joint (A, B)");
  std::filesystem::remove_all(folder);
}

TEST_CASE("mechanism --animate turns a slot's block with its line at every frame, as the CSV's joints give it",
          "[cli][mechanism][drawing]") {
  const std::string folder = temporary_folder();
  // The block at A slides in the slot of a turning link: O4-B (Whitworth, which turns fully) and B-C
  // (the inverted slider-crank's rocker, which rocks).
  struct Slot {
    std::string model, from, to;
  };
  for (const Slot& slot : {Slot{"whitworth", "O4", "B"}, Slot{"inverted-slider-crank", "B", "C"}}) {
    INFO(slot.model);
    const std::string file = folder + "/" + slot.model + ".svg";
    const ProgramRun run = run_numlab("mechanism " + slot.model + ".toml --sweep 0:355:5 --animate " + file + " --format csv");
    REQUIRE(run.exit_code == 0);
    const auto rows = csv_rows(run.out);
    REQUIRE(rows.size() == 72);
    for (const auto& row : rows) REQUIRE(row.at("status") == "converged");
    const std::string svg = read_all(file);
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, std::regex("transform=\"rotate\\(([-0-9.]+)\\)\"[^>]*><animateTransform attributeName=\"transform\" "
                                                 "type=\"rotate\" dur=\"[0-9.]+s\" repeatCount=\"indefinite\" values=\"([^\"]*)\"")));
    std::vector<double> angles;
    std::istringstream list(m[2].str());
    for (std::string value; std::getline(list, value, ';');) angles.push_back(std::stod(value));
    REQUIRE(angles.size() == rows.size() + 1);  // every pose, then back to the first
    CHECK(std::stod(m[1]) == angles[0]);        // the still picture is the first frame's
    // SVG's y runs down: the block's angle is minus the line's, atan2 of from -> to, to the 1e-6 deg
    // the SVG prints (6 decimals); the next frame within half a turn, so it never spins the long way.
    for (std::size_t k = 0; k < angles.size(); ++k) {
      const auto& row = rows[k % rows.size()];
      const double dx = std::stod(row.at("x_" + slot.to)) - std::stod(row.at("x_" + slot.from));
      const double dy = std::stod(row.at("y_" + slot.to)) - std::stod(row.at("y_" + slot.from));
      const double expected = -std::atan2(dy, dx) * 180.0 / 3.14159265358979323846;
      INFO("frame " << k << ": " << angles[k] << " against " << expected);
      CHECK(std::abs(std::remainder(angles[k] - expected, 360.0)) <= 1e-6);
      if (k > 0) CHECK(std::abs(angles[k] - angles[k - 1]) < 180.0);
    }
  }
  std::filesystem::remove_all(folder);
}
