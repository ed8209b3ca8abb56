// Charts drawn by gnuplot (labs/output/chart.cpp) are whole or absent: gnuplot draws into a temporary
// beside the chart, renamed into place only when gnuplot exited 0 and the file is complete. Its
// warnings never reach stdout. A fake gnuplot put first on PATH plays a full disk.

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "run_numlab.hpp"

using namespace numlab::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const std::string nist = NUMLAB_NIST_DIR;

// While alive, PATH starts with a folder whose `gnuplot` is the given shell script body. The script
// is called as gnuplot -e "numlab_output='TEMPORARY'" SCRIPT, so it finds the file to write in $2.
class FakeGnuplot {
 public:
  explicit FakeGnuplot(const std::string& body) : folder_(temporary_folder()), old_path_(std::getenv("PATH")) {
    const std::string program = folder_ + "/gnuplot";
    std::ofstream(program) << "#!/bin/sh\nout=$(printf '%s' \"$2\" | sed \"s/^numlab_output='//; s/'\\$//\")\n" << body << "\n";
    chmod(program.c_str(), 0755);
    setenv("PATH", (folder_ + ":" + old_path_).c_str(), 1);
  }
  ~FakeGnuplot() {
    setenv("PATH", old_path_.c_str(), 1);
    std::filesystem::remove_all(folder_);
  }
  FakeGnuplot(const FakeGnuplot&) = delete;
  FakeGnuplot& operator=(const FakeGnuplot&) = delete;

 private:
  std::string folder_;
  std::string old_path_;
};

std::vector<std::string> names_in(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// `fit --chart FOLDER/NAME` failed as bad input naming the chart and `problem`, and left only the
// chart's data and script: no chart, no temporary.
void check_chart_refused(const std::string& name, const std::string& problem) {
  const std::string folder = temporary_folder();
  const std::string chart = folder + "/" + name;
  require_bad_input("fit --data " + nist + "/Norris.dat --degree 1 --chart " + chart,
                    "cannot write '" + chart + "': " + problem);
  CHECK(names_in(folder) == std::vector<std::string>{name + ".data.csv", name + ".gp"});
  std::filesystem::remove_all(folder);
}

}  // namespace

TEST_CASE("A chart gnuplot leaves truncated is refused and removed, named by its own name", "[cli][chart]") {
  {
    const FakeGnuplot half_svg("printf '<?xml version=\"1.0\"?>\\n<svg width=\"900\">\\n<g>' > \"$out\"; exit 0");
    check_chart_refused("c.svg", "gnuplot wrote a truncated SVG, without its closing </svg> (is the disk full?)");
  }
  {
    const FakeGnuplot empty(": > \"$out\"; exit 0");
    check_chart_refused("c.svg", "gnuplot wrote an empty chart (is the disk full?)");
  }
  {
    const FakeGnuplot half_png("printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\rIHDR' > \"$out\"; exit 0");
    check_chart_refused("c.png", "gnuplot wrote a truncated PNG, without its IEND chunk (is the disk full?)");
  }
  {
    const FakeGnuplot failing("printf '<svg>\\n</svg>\\n' > \"$out\"; echo '  line 9: all points y value undefined!' >&2; exit 1");
    check_chart_refused("c.svg", "gnuplot exited with status 1: line 9: all points y value undefined!");
  }
  {
    const FakeGnuplot killed("printf '<svg>' > \"$out\"; kill -XFSZ $$");
    check_chart_refused("c.svg", "gnuplot was killed by signal 25");
  }
  // No gnuplot on PATH at all.
  const std::string path = std::getenv("PATH");
  const std::string empty = temporary_folder();
  setenv("PATH", empty.c_str(), 1);
  check_chart_refused("c.svg", "gnuplot is not installed (run: bash .ci/setup)");
  setenv("PATH", path.c_str(), 1);
  std::filesystem::remove_all(empty);
}

TEST_CASE("gnuplot's warnings stay off stdout, so --format json stays JSON", "[cli][chart]") {
  const FakeGnuplot chatty("echo 'Warning: empty x range'; echo 'Warning: on stderr' >&2; printf '<svg>\\n</svg>\\n' > \"$out\"");
  const std::string folder = temporary_folder();
  const ProgramRun run =
      run_numlab("fit --data " + nist + "/Norris.dat --degree 1 --chart " + folder + "/c.svg --format json");
  CHECK(run.exit_code == 0);
  CHECK(run.err.empty());
  CHECK(nlohmann::json::parse(run.out)["status"] == "converged");
  CHECK(read_all(folder + "/c.svg") == "<svg>\n</svg>\n");
  CHECK(names_in(folder) == std::vector<std::string>{"c.svg", "c.svg.data.csv", "c.svg.gp"});
  std::filesystem::remove_all(folder);
}

TEST_CASE("The real gnuplot on a disk that fills up (RLIMIT_FSIZE): no chart, the chart named", "[cli][chart]") {
  const std::string folder = temporary_folder();
  // 16 KiB (32 blocks of 512 bytes in sh): room for the data (2 KiB) and the script, not for the
  // SVG (43 KiB). gnuplot gets SIGXFSZ at the limit; numlab, whose own files are small, reports it.
  const std::string command = "ulimit -f 32; exec " + std::string(NUMLAB_BINARY) + " fit --data " + nist +
                              "/Norris.dat --degree 1 --chart " + folder + "/c.svg </dev/null >" + folder +
                              "/out 2>" + folder + "/err";
  const int status = std::system(command.c_str());
  const std::string err = read_all(folder + "/err");
  INFO("stderr: " << err);
  CHECK(WEXITSTATUS(status) == 2);
  CHECK_THAT(err, StartsWith("numlab: error: cannot write '" + folder + "/c.svg': gnuplot"));
  CHECK(names_in(folder) == std::vector<std::string>{"c.svg.data.csv", "c.svg.gp", "err", "out"});
  std::filesystem::remove_all(folder);
}

TEST_CASE("A chart's script redraws the chart by hand, at its own name", "[cli][chart]") {
  const std::string folder = temporary_folder();
  const ProgramRun run = run_numlab("fit --data " + nist + "/Norris.dat --degree 1 --chart " + folder + "/c.svg");
  REQUIRE(run.exit_code == 0);
  const std::string drawn = read_all(folder + "/c.svg");
  CHECK_THAT(drawn, Contains("</svg>"));
  std::filesystem::remove(folder + "/c.svg");
  CHECK(std::system(("cd / && gnuplot " + folder + "/c.svg.gp >/dev/null 2>&1").c_str()) == 0);
  CHECK(read_all(folder + "/c.svg") == drawn);
  std::filesystem::remove_all(folder);
}

namespace {

// The shipped four-bar with, as asked, its rocker Q-B as the output and loads (a torque of -10 on the
// rocker, 2 kg at B), written into `folder`.
std::string four_bar_file(const std::string& folder, bool loads, bool output) {
  std::string text = read_all(std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml");
  if (output) text.replace(text.find("[ground]"), 8, "output = \"Q-B\"\n\n[ground]");
  if (loads) text += "\n[[load]]\nlink = \"Q-B\"\ntorque = -10.0\n\n[[load]]\njoint = \"B\"\nmass = 2.0\n";
  const std::string file = folder + "/four-bar-loaded.toml";
  std::ofstream(file) << text;
  return file;
}

// The lines of a text, blank ones included.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; begin = end + 1, end = text.find('\n', begin)) {
    lines.push_back(text.substr(begin, end - begin));
  }
  return lines;
}

// The comma-separated cells of a line.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells(1);
  for (const char c : line) {
    if (c == ',') cells.emplace_back();
    else cells.back().push_back(c);
  }
  return cells;
}

}  // namespace

TEST_CASE("mechanism --chart: the driving torque and the mechanical advantage are the CSV's, the chart whole", "[cli][chart][mechanism]") {
  const std::string folder = temporary_folder(), files = temporary_folder();
  const std::string file = four_bar_file(files, true, true);
  const ProgramRun run = run_numlab("mechanism " + file + " --sweep 0:355:5 --chart " + folder + "/torque.svg --format csv");
  REQUIRE(run.exit_code == 0);
  CHECK(names_in(folder) == std::vector<std::string>{"torque.svg", "torque.svg.data.csv", "torque.svg.gp"});
  CHECK_THAT(read_all(folder + "/torque.svg"), Contains("</svg>"));
  CHECK_THAT(read_all(folder + "/torque.svg.gp"), Contains("driving torque and mechanical advantage"));
  // The report's CSV: its columns by name.
  const auto report = lines_of(run.out);
  const auto header = cells_of(report[0]);
  auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    REQUIRE(at != header.end());
    return static_cast<std::size_t>(at - header.begin());
  };
  const std::size_t crank = column("crank_deg"), torque = column("driver_torque"), advantage = column("mechanical_advantage_Q-B");
  // The chart's data: one row per pose in the same order, a blank line where a pole breaks the curve;
  // the same digits, an empty cell where the CSV says inf.
  const auto data = lines_of(read_all(folder + "/torque.svg.data.csv"));
  REQUIRE(data[0] == "driver,driver_torque,statics,mechanical_advantage");
  std::size_t pose = 1, breaks = 0;
  for (std::size_t k = 1; k < data.size(); ++k) {
    if (data[k].empty()) {
      ++breaks;
      continue;
    }
    REQUIRE(pose < report.size());
    const auto chart = cells_of(data[k]), csv = cells_of(report[pose++]);
    INFO("chart: " << data[k] << "\ncsv: " << report[pose - 1]);
    CHECK(chart[0] == csv[crank]);
    CHECK(chart[1] == (csv[torque] == "inf" ? "" : csv[torque]));
    CHECK(chart[2] == "equilibrium");
    CHECK(chart[3] == (csv[advantage] == "inf" || csv[advantage] == "-inf" ? "" : csv[advantage]));
  }
  CHECK(pose == report.size());
  CHECK(pose == 73);
  // The rocker stands still twice a turn (its toggles): the advantage's two poles break the curve.
  CHECK(breaks == 2);
  std::filesystem::remove_all(folder);
  std::filesystem::remove_all(files);
}

TEST_CASE("mechanism --chart without loads charts the mechanical advantage only, without an output too it is refused",
          "[cli][chart][mechanism]") {
  const std::string folder = temporary_folder(), files = temporary_folder();
  const std::string unloaded = four_bar_file(files, false, true);
  REQUIRE(run_numlab("mechanism " + unloaded + " --sweep 0:355:5 --chart " + folder + "/ma.svg").exit_code == 0);
  CHECK_THAT(read_all(folder + "/ma.svg.gp"), Contains("mechanical advantage only (no [[load]] in the file: no driving torque)"));
  CHECK_THAT(read_all(folder + "/ma.svg"), Contains("</svg>"));
  require_bad_input("mechanism four-bar --sweep 0:355:5 --chart " + folder + "/none.svg",
                    "--chart: four-bar has no [[load]] and no output, nothing to chart: add loads or give --output LINK");
  require_bad_input("mechanism four-bar --crank 30 --output Q-B --chart " + folder + "/one.svg",
                    "--chart applies only to --sweep (it charts the sweep)");
  CHECK(names_in(folder) == std::vector<std::string>{"ma.svg", "ma.svg.data.csv", "ma.svg.gp"});
  std::filesystem::remove_all(folder);
  std::filesystem::remove_all(files);
}

TEST_CASE("mechanism --chart when gnuplot fails or leaves the chart truncated: no chart, its data and script, exit 2",
          "[cli][chart][mechanism]") {
  const std::string files = temporary_folder();
  const std::string file = four_bar_file(files, true, true);
  for (const auto& [body, problem] : {std::pair<std::string, std::string>{"echo 'line 9: all points y value undefined!'; exit 1",
                                                                          "gnuplot exited with status 1: line 9: all points y value undefined!"},
                                      {"printf '<svg>' > \"$out\"", "gnuplot wrote a truncated SVG, without its closing </svg>"}}) {
    INFO(body);
    const FakeGnuplot failing(body);
    const std::string folder = temporary_folder();
    require_bad_input("mechanism " + file + " --sweep 0:355:5 --chart " + folder + "/torque.svg",
                      "cannot write '" + folder + "/torque.svg': " + problem);
    CHECK(names_in(folder) == std::vector<std::string>{"torque.svg.data.csv", "torque.svg.gp"});
    std::filesystem::remove_all(folder);
  }
  std::filesystem::remove_all(files);
}
