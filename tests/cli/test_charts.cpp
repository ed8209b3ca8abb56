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
