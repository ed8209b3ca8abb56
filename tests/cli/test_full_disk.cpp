// Files written whole or not at all when the disk fills (docs/cli.md, "Files a command writes"): each
// output of issues 30 and 31 (mechanism --svg, --animate, --html, --chart, the CSV and JSON of
// --sweep and --drivers on stdout, exercise check --out's trace.html) written under a file-size
// limit, `sh -c "trap '' XFSZ; ulimit -f 16; exec numlab ..."` (8 KiB in sh's 512-byte blocks: writes
// past it fail with EFBIG instead of killing numlab). Each must give one line naming the file and
// the error, exit 2, leave the file absent (or as it was), no temporary beside it, nothing else
// written. Each output is first made without the limit, to show it is larger than the limit.

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "run_numlab.hpp"

namespace fs = std::filesystem;
using numlab::test::read_all;
using numlab::test::temporary_folder;

namespace {

const std::string models = NUMLAB_MODELS_DIR;
const std::string mechanism = "mechanism " + models;

struct LimitedRun {
  int exit_code = -1;
  std::string err;
};

// numlab ARGUMENTS run in `folder`, stdout to `folder`/`stdout_name` (or outside it when empty),
// stderr outside it; with the file-size limit (`blocks` of sh's ulimit -f) when `limited`.
LimitedRun run_in(const std::string& folder, const std::string& arguments, bool limited, const std::string& stdout_name = "",
                  int blocks = 16) {
  const std::string outside = folder + ".out";
  const std::string stdout_path = stdout_name.empty() ? outside : folder + "/" + stdout_name;
  const std::string command = "cd '" + folder + "' && " + (limited ? "trap '' XFSZ && ulimit -f " + std::to_string(blocks) + " && " : std::string()) + "exec " +
                              NUMLAB_BINARY + " " + arguments + " </dev/null >'" + stdout_path + "' 2>'" + folder + ".err'";
  const int status = std::system(command.c_str());  // sh -c COMMAND
  LimitedRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(folder + ".err")};
  fs::remove(folder + ".err");
  fs::remove(outside);
  return run;
}

std::set<std::string> names_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) names.insert(fs::relative(entry.path(), folder).string());
  return names;
}

// The output `target` of `arguments` is larger than the limit without it; with it the run fails
// cleanly and the folder holds exactly `left` (names), with `kept` files unchanged.
void check_whole_or_absent(const std::string& arguments, const std::string& target, const std::set<std::string>& left,
                           const std::string& stdout_name = "", const std::set<std::string>& kept = {}) {
  INFO("numlab " << arguments);
  const std::string free_folder = temporary_folder();
  REQUIRE(run_in(free_folder, arguments, false, stdout_name).exit_code <= 1);
  REQUIRE(fs::exists(free_folder + "/" + target));
  CHECK(fs::file_size(free_folder + "/" + target) > 16 * 1024);  // larger than the limit in either block size
  fs::remove_all(free_folder);

  const std::string folder = temporary_folder();
  for (const std::string& name : kept) std::ofstream(folder + "/" + name) << "an earlier " << name << "\n";
  const LimitedRun run = run_in(folder, arguments, true, stdout_name);
  INFO("stderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  CHECK_THAT(run.err, Catch::Matchers::StartsWith("numlab: error: cannot write ") && Catch::Matchers::Contains(target) &&
                          Catch::Matchers::Contains("File too large"));
  CHECK(names_in(folder) == left);  // no temporary (.NAME.tmp-XXXXXX), nothing else
  if (stdout_name.empty() && kept.count(target) == 0) CHECK_FALSE(fs::exists(folder + "/" + target));
  for (const std::string& name : kept) CHECK(read_all(folder + "/" + name) == "an earlier " + name + "\n");
  fs::remove_all(folder);
}

}  // namespace

TEST_CASE("mechanism's drawings and page are whole or absent when the disk fills", "[cli][full-disk]") {
  const std::string whitworth = mechanism + "/whitworth.toml --sweep 0:359:1";
  check_whole_or_absent(whitworth + " --svg a.svg", "a.svg", {});
  check_whole_or_absent(whitworth + " --animate a.svg", "a.svg", {});
  check_whole_or_absent(whitworth + " --html a.html", "a.html", {});
  check_whole_or_absent(whitworth + " --svg a.svg --out drawings", "drawings/a.svg", {"drawings"});
  // An earlier file of that name stays as it was.
  check_whole_or_absent(whitworth + " --html a.html", "a.html", {"a.html"}, "", {"a.html"});
}

TEST_CASE("mechanism's drawings, page and chart of one run: all of them in place, or none", "[cli][full-disk]") {
  // 9 poses: the pose (4 KB) and the animation (6 KB) each fit under 30 blocks (15 KiB in sh's
  // 512-byte blocks, 30 KiB in bash's), the page (54 KB) and the chart (35 KB) do not.
  const std::string run = mechanism + "/whitworth.toml --sweep 0:10:5 --svg a.svg --animate c.svg";
  for (const std::string& last : {std::string(" --html b.html"), std::string(" --chart d.svg")}) {
    INFO("numlab " << run << last);
    const std::string free_folder = temporary_folder();
    REQUIRE(run_in(free_folder, run + last, false).exit_code == 0);
    CHECK(std::max(fs::file_size(free_folder + "/a.svg"), fs::file_size(free_folder + "/c.svg")) < 15 * 1024);
    CHECK(fs::file_size(free_folder + (last.find("html") != std::string::npos ? "/b.html" : "/d.svg")) > 30 * 1024);
    fs::remove_all(free_folder);

    const std::string folder = temporary_folder();
    std::ofstream(folder + "/a.svg") << "an earlier a.svg\n";
    const LimitedRun limited = run_in(folder, run + last, true, "", 30);
    INFO("stderr: " << limited.err);
    CHECK(limited.exit_code == 2);
    CHECK(std::count(limited.err.begin(), limited.err.end(), '\n') == 1);
    // The earlier a.svg as it was, no c.svg, no temporaries; a chart's data and script stay.
    CHECK(read_all(folder + "/a.svg") == "an earlier a.svg\n");
    const std::set<std::string> left = last.find("html") != std::string::npos
                                           ? std::set<std::string>{"a.svg"}
                                           : std::set<std::string>{"a.svg", "d.svg.data.csv", "d.svg.gp"};
    CHECK(names_in(folder) == left);
    fs::remove_all(folder);
  }
}

TEST_CASE("the built-in jansen and mustang: drawings and page of one run all in place, or none", "[cli][full-disk]") {
  // Under 50 blocks (25 KiB in sh's, 50 KiB in bash's) the pose and the animation fit, the page not.
  for (const std::string name : {"jansen", "mustang"}) {
    const std::string run = "mechanism " + name + " --sweep 0:50:10 --svg a.svg --animate c.svg --html b.html";
    INFO("numlab " << run);
    const std::string free_folder = temporary_folder();
    REQUIRE(run_in(free_folder, run, false).exit_code == 0);
    CHECK(std::max(fs::file_size(free_folder + "/a.svg"), fs::file_size(free_folder + "/c.svg")) < 25 * 1024);
    CHECK(fs::file_size(free_folder + "/b.html") > 50 * 1024);
    fs::remove_all(free_folder);
    const std::string folder = temporary_folder();
    const LimitedRun limited = run_in(folder, run, true, "", 50);
    CHECK(limited.exit_code == 2);
    CHECK(limited.err == "numlab: error: cannot write 'b.html': File too large\n");
    CHECK(names_in(folder).empty());
    fs::remove_all(folder);
  }
}

TEST_CASE("mechanism --chart: the chart whole or absent when the disk fills; its data and script stay", "[cli][full-disk]") {
  // 360 poses: the data file itself is past the limit, so nothing is written.
  check_whole_or_absent(mechanism + "/whitworth.toml --sweep 0:359:1 --chart c.svg", "c.svg.data.csv", {});
  // 9 poses: data and script fit; gnuplot's SVG does not, and numlab refuses the truncated chart.
  const std::string folder = temporary_folder();
  const LimitedRun run = run_in(folder, mechanism + "/whitworth.toml --sweep 0:40:5 --chart c.svg", true);
  INFO("stderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.err, Catch::Matchers::StartsWith("numlab: error: cannot write 'c.svg': gnuplot wrote a truncated SVG"));
  CHECK(names_in(folder) == std::set<std::string>{"c.svg.data.csv", "c.svg.gp"});
  fs::remove_all(folder);
}

TEST_CASE("mechanism's CSV and JSON on a redirected stdout: a cut-short result is an error naming the file", "[cli][full-disk]") {
  // The shell made the file, so numlab cannot remove it: it says it is cut short, and exits 2.
  check_whole_or_absent(mechanism + "/whitworth.toml --sweep 0:359:1 --format csv", "o.csv", {"o.csv"}, "o.csv");
  check_whole_or_absent(mechanism + "/whitworth.toml --sweep 0:359:1 --format json", "o.json", {"o.json"}, "o.json");
  // Two drivers along a 120-row path (a circle of 30 deg about 90, 90).
  const std::string path_folder = temporary_folder();
  std::ofstream path(path_folder + "/path.csv");
  path << "crank_deg,crank2_deg\n";
  for (int k = 0; k < 120; ++k) path << 90.0 + 30.0 * std::cos(k * 3.0 * 3.14159265 / 180.0) << "," << 90.0 + 30.0 * std::sin(k * 3.0 * 3.14159265 / 180.0) << "\n";
  path.close();
  check_whole_or_absent(mechanism + "/five-bar.toml --drivers " + path_folder + "/path.csv --format csv", "d.csv", {"d.csv"}, "d.csv");
  fs::remove_all(path_folder);
}

TEST_CASE("exercise check --out: trace.html whole or absent when the disk fills", "[cli][full-disk]") {
  // GEPP without pivoting (the shipped mutant) fails the trace check, so trace.html (21 KB) is written.
  const std::string source = models + "/../..";
  const std::string mutant_folder = temporary_folder();
  const std::string mutant = mutant_folder + "/gepp_no_pivoting.py";
  REQUIRE(std::system((std::string(NUMLAB_PYTHON3) + " " + source + "/tests/exercises/apply_mutant.py " + source +
                       "/tests/exercises/mutants/gepp/no_pivoting.patch " + mutant)
                          .c_str()) == 0);
  const std::string arguments = "exercise check gepp --out out -- " + std::string(NUMLAB_PYTHON3) + " " + mutant;
  const std::string free_folder = temporary_folder();
  CHECK(run_in(free_folder, arguments, false).exit_code == 1);
  REQUIRE(fs::exists(free_folder + "/out/trace.html"));
  CHECK(fs::file_size(free_folder + "/out/trace.html") > 16 * 1024);
  fs::remove_all(free_folder);

  const std::string folder = temporary_folder();
  const LimitedRun run = run_in(folder, arguments, true);
  INFO("stderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.err == "numlab: error: cannot write 'out/trace.html': File too large\n");
  // The folder is made and tried before any work; nothing in it, no temporary.
  CHECK(names_in(folder) == std::set<std::string>{"out"});
  fs::remove_all(folder);
  fs::remove_all(mutant_folder);
}
