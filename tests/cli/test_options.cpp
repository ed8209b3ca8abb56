// The shared flags under hostile input (docs/cli.md): every value checked as it is parsed, every flag
// honoured where it is accepted or rejected with where it applies, output files that never land
// outside the folder asked for nor on an input, and --step with and without a terminal.

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "run_numlab.hpp"

using Catch::Matchers::Contains;
using numlab::test::ProgramRun;
using numlab::test::require_bad_input;
using numlab::test::run_numlab;
using numlab::test::temporary_folder;

namespace {

namespace fs = std::filesystem;

std::string file_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

std::vector<std::string> entries(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) names.push_back(entry.path().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs numlab with `folder` as the working directory (stdin from /dev/null), so that a test can
// see every file it wrote.
ProgramRun run_in(const std::string& folder, const std::string& arguments) {
  const std::string logs = temporary_folder();
  const std::string command = "cd '" + folder + "' && " + std::string(NUMLAB_BINARY) + " " + arguments +
                              " </dev/null >" + logs + "/out 2>" + logs + "/err";
  const int status = std::system(command.c_str());
  ProgramRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_text(logs + "/out"), file_text(logs + "/err")};
  fs::remove_all(logs);
  return run;
}

// Bad input, run in an empty folder: exit 2, one error line naming `named`, and no file written.
void require_rejected_writing_nothing(const std::string& arguments, const std::string& named) {
  const std::string folder = temporary_folder();
  const ProgramRun run = run_in(folder, arguments);
  INFO("numlab " << arguments << "\nstderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Catch::Matchers::StartsWith("numlab: error: ") && Contains(named));
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  CHECK(entries(folder).empty());
  fs::remove_all(folder);
}

// Every sub-command that honours --tol, with the rest of a valid command line.
const std::vector<std::string> commands_with_tol = {
    "solve linear --method gepp --generate random:3",
    "solve nonlinear --problem rosenbrock --method newton",
    "mechanism jansen --crank 10",
    "mechanism mustang --crank 45",
    "fit --foot-path upper --degree 2 --linear gauss-seidel",
    "bench jansen --quick",
    "bench mustang --quick",
};

bool have_script() { return std::system("command -v script >/dev/null 2>&1") == 0; }

// Runs numlab at a terminal (a pty made by util-linux `script`), typing `typed` (a shell printf
// argument; sleeps allowed between parts). stdout and stderr both arrive in `out`.
ProgramRun run_at_terminal(const std::string& typed_script, const std::string& arguments) {
  const std::string logs = temporary_folder();
  const std::string command = "(" + typed_script + ") | script -qec \"" + std::string(NUMLAB_BINARY) + " " +
                              arguments + "\" /dev/null >" + logs + "/out 2>&1";
  const int status = std::system(command.c_str());
  ProgramRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_text(logs + "/out"), ""};
  fs::remove_all(logs);
  return run;
}

}  // namespace

TEST_CASE("Option --tol: a finite number >= 0, for every sub-command that takes it; never an abort", "[cli][options]") {
  for (const std::string& command : commands_with_tol) {
    for (const std::string value : {"abc", "1e400", "-1e400", "inf", "-inf", "nan", "-1", "''", "1e-3x", "0x1p-3"}) {
      require_rejected_writing_nothing(command + " --tol " + value, "--tol: must be a finite number >= 0");
    }
  }
  require_bad_input("solve nonlinear --problem rosenbrock --method newton --step-tol 1e400",
                    "--step-tol: must be a finite number >= 0");
  // 0 is a tolerance (stop only at an exact zero, or at the iteration limit).
  CHECK(run_numlab("solve nonlinear --problem rosenbrock --method newton --tol 0").exit_code != 2);
}

TEST_CASE("Option --max-iter: a whole number from 1 to 1e8, said in one short line", "[cli][options]") {
  for (const std::string value : {"0", "-3", "1.5", "1e3", "abc", "100000001", "99999999999999999999", "''"}) {
    const ProgramRun run = run_numlab("solve nonlinear --problem rosenbrock --method newton --max-iter " + value);
    INFO(value << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("--max-iter: must be a whole number from 1 to 100000000, got"));
    CHECK(run.err.size() < 120);
  }
  CHECK(run_numlab("solve nonlinear --problem rosenbrock --method newton --max-iter 1").exit_code == 1);
}

TEST_CASE("Option --format: exactly text, json or csv (any case), no CLI11 internals", "[cli][options]") {
  for (const std::string value : {"xml", "1", "0", "''", "jsonx"}) {
    const ProgramRun run = run_numlab("solve linear --method gepp --generate random:3 --format " + value);
    INFO(value << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.err, Contains("--format: must be text, json or csv, got"));
    CHECK(run.err.find("->") == std::string::npos);
  }
  const ProgramRun upper = run_numlab("solve linear --method gepp --generate random:3 --format JSON");
  CHECK(upper.exit_code == 0);
  CHECK(nlohmann::json::parse(upper.out)["status"] == "converged");
}

TEST_CASE("A shared flag a sub-command does not honour is rejected, naming where it applies", "[cli][options]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lab gauss --format json", "--format json does not apply to numlab lab (it applies to: solve linear"},
      {"lab gauss --format csv", "--format csv does not apply to numlab lab"},
      {"lab gauss --trace", "--trace does not apply to numlab lab"},
      {"lab gauss --tol 1e-3", "--tol does not apply to numlab lab"},
      {"lab gauss --max-iter 3", "--max-iter does not apply to numlab lab"},
      {"solve linear --method gepp --generate random:3 --out x", "--out does not apply to numlab solve linear"},
      {"solve nonlinear --problem wood --method newton --out x", "--out does not apply to numlab solve nonlinear"},
      {"fit --foot-path upper --degree 2 --step", "--step does not apply to numlab fit"},
      {"bench jansen --quick --chart a.svg", "--chart applies only to bench all, bench linear and bench fit"},
      {"bench mustang --quick --chart a.svg", "--chart applies only to"},
      {"bench jansen --quick --sizes 2", "--sizes applies only to bench linear"},
      {"bench all --quick --sizes 2", "--sizes applies only to bench linear"},
      {"bench fit --quick --sizes 2", "--sizes applies only to bench linear"},
      {"bench jansen --quick --out x", "--out does not apply to numlab bench jansen"},
      {"bench mustang --quick --format csv", "--format csv does not apply to numlab bench mustang"},
      {"bench all --quick --format csv", "--format csv does not apply to numlab bench all"},
      {"bench linear --quick --tol 1e-3", "--tol does not apply to numlab bench linear"},
      {"bench linear --quick --trace", "--trace does not apply to numlab bench linear"},
      {"bench fit --quick --step", "--step does not apply to numlab bench fit"},
      {"bench fit --quick --max-iter 4", "--max-iter does not apply to numlab bench fit"},
      // Method-specific flags.
      {"solve nonlinear --problem rosenbrock --method gsl-newton --damped", "--damped applies only to --method newton"},
      {"solve nonlinear --problem rosenbrock --method gsl-hybrids --linear gepp", "--linear applies only to --method newton"},
      {"solve linear --method gsl-lu --generate random:3 --trace", "--trace applies only to the hand-written methods"},
      {"solve linear --method eigen-lu --generate random:3 --step", "--step applies only to the hand-written methods"},
      {"solve linear --method gsl-qr --generate random:3 --tol 1e-3", "--tol applies only to the hand-written methods"},
      {"solve linear --method gepp --generate random:3 --max-iter 5", "--max-iter applies only to gauss-seidel"},
      {"mechanism jansen --crank 10 --solver sequential --linear gepp", "--linear applies only to --solver full"},
      {"mechanism mustang --crank 45 --solver analytic --tol 1e-3", "--tol applies only to the iterative solvers"},
      {"mechanism jansen --crank 10 --solver analytic --max-iter 3", "--max-iter applies only to the iterative solvers"},
      {"mechanism jansen --crank 10 --beest-animated", "--beest-animated applies only to --beest FILE"},
      {"fit --foot-path upper --degree 2 --method gsl --trace", "--trace applies only to --method normal and normal-scaled"},
      {"fit --foot-path upper --degree 2 --method eigen-qr --linear gauss-seidel", "--linear applies only to --method normal"},
      {"fit --foot-path upper --degree 2 --tol 1e-3", "--tol applies only to --linear gauss-seidel"},
      {"fit --foot-path upper --degree 2 --max-iter 3", "--max-iter applies only to --linear gauss-seidel"},
  };
  for (const auto& [arguments, named] : cases) require_rejected_writing_nothing(arguments, named);

  const std::string matrix = numlab::test::temporary_file("a.txt", "2 1\n1 3\n");
  require_rejected_writing_nothing("solve linear --method gepp --matrix " + matrix + " --seed 3",
                                   "--seed applies only to --generate");
}

TEST_CASE("Option --trace goes to stderr under --format csv; stdout stays CSV", "[cli][options][trace]") {
  const ProgramRun nonlinear = run_numlab("solve nonlinear --problem wood --method newton --trace --format csv");
  CHECK(nonlinear.exit_code == 0);
  CHECK(nonlinear.out.starts_with("problem,method,status,"));
  CHECK(std::count(nonlinear.out.begin(), nonlinear.out.end(), '\n') == 2);
  CHECK_THAT(nonlinear.err, Contains("||f||_inf") && Contains("linear solve"));

  const ProgramRun linear = run_numlab("solve linear --method gepp --generate gs-diverge --trace --format csv");
  CHECK(linear.exit_code == 0);
  CHECK(linear.out.starts_with("method,n,status,"));
  CHECK_THAT(linear.err, Contains("swap rows 1 and 3"));

  const ProgramRun mustang = run_numlab("mechanism mustang --sweep 40:50:5 --trace --format csv");
  CHECK(mustang.exit_code == 0);
  CHECK(mustang.out.starts_with("crank_deg,"));
  CHECK_THAT(mustang.err, Contains("kappa(J)"));
}

TEST_CASE("Option --step implies --trace; without a terminal it never pauses and says so once", "[cli][options][step]") {
  for (const std::string arguments : {"solve nonlinear --problem wood --method newton --step --format json",
                                      "solve linear --method gauss-seidel --generate diag-dominant:4 --step --format json",
                                      "mechanism jansen --sweep 0:10:5 --step --format json",
                                      "mechanism mustang --sweep 40:50:5 --step --format json"}) {
    const ProgramRun run = run_numlab(arguments);
    INFO(arguments << "\n" << run.err);
    CHECK(run.exit_code == 0);
    const auto out = nlohmann::json::parse(run.out);
    CHECK(out.contains("trace"));
    CHECK(out["trace"].size() > 0);
    CHECK(run.err.find("Enter") == std::string::npos);
    const std::string note = "numlab: note: --step pauses only when stdin is a terminal";
    // One note, at the first step, however many steps follow.
    const std::size_t first = run.err.find(note);
    CHECK(first != std::string::npos);
    CHECK(run.err.find(note, first + 1) == std::string::npos);
  }
}

TEST_CASE("Relative output files go inside --out when it is given", "[cli][options][files]") {
  const std::string cwd = temporary_folder();
  const ProgramRun fit = run_in(cwd, "fit --foot-path upper --degree 3 --chart arc.svg --out results");
  INFO(fit.err);
  CHECK(fit.exit_code == 0);
  for (const char* name : {"arc.svg", "arc.svg.data.csv", "arc.svg.gp"}) CHECK(fs::exists(cwd + "/results/" + name));
  const ProgramRun pose = run_in(cwd, "mechanism jansen --crank 10 --svg pose.svg --animate walk.svg --out results");
  CHECK(pose.exit_code == 0);
  CHECK(fs::file_size(cwd + "/results/pose.svg") > 1000);
  CHECK(fs::file_size(cwd + "/results/walk.svg") > 1000);
  // Nothing else in the working directory, and no temporaries anywhere.
  CHECK(entries(cwd) == std::vector<std::string>{cwd + "/results", cwd + "/results/arc.svg", cwd + "/results/arc.svg.data.csv",
                                                 cwd + "/results/arc.svg.gp", cwd + "/results/pose.svg",
                                                 cwd + "/results/walk.svg"});
  fs::remove_all(cwd);
}

TEST_CASE("An output never overwrites an input, nor lands on a folder, nor is written twice", "[cli][options][files]") {
  const std::string folder = temporary_folder();
  const std::string data = "x,y\n1,2\n2,3\n3,5\n4,4\n";
  std::ofstream(folder + "/mydata.csv") << data;
  // The chart's companions keep the chart's whole name: mydata.csv is left alone.
  const ProgramRun fit = run_in(folder, "fit --data mydata.csv --degree 1 --chart mydata.svg");
  INFO(fit.err);
  CHECK(fit.exit_code == 0);
  CHECK(file_text(folder + "/mydata.csv") == data);
  CHECK(fs::exists(folder + "/mydata.svg.data.csv"));
  CHECK(fs::exists(folder + "/mydata.svg.gp"));

  // An input named like a companion is refused before any work.
  std::ofstream(folder + "/in.svg.data.csv") << data;
  const auto before = entries(folder);
  const ProgramRun clash = run_in(folder, "fit --data in.svg.data.csv --degree 1 --chart in.svg");
  CHECK(clash.exit_code == 2);
  CHECK_THAT(clash.err, Contains("is the input file") && Contains("in.svg.data.csv"));
  CHECK(file_text(folder + "/in.svg.data.csv") == data);
  CHECK(entries(folder) == before);

  // A folder as a target: exit 2, no .partial and no temporary left.
  fs::create_directory(folder + "/taken.svg");
  const ProgramRun onto_folder = run_in(folder, "mechanism jansen --crank 10 --svg taken.svg");
  CHECK(onto_folder.exit_code == 2);
  CHECK_THAT(onto_folder.err, Contains("--svg 'taken.svg' is a folder"));
  const ProgramRun bench_onto_folder = run_in(folder, "bench linear --quick --sizes 2 --chart taken.svg");
  CHECK(bench_onto_folder.exit_code == 2);
  for (const auto& name : entries(folder)) {
    CHECK(name.find(".partial") == std::string::npos);
    CHECK(name.find(".tmp-") == std::string::npos);
  }
  CHECK(fs::is_empty(folder + "/taken.svg"));

  // The same file twice among the outputs.
  const ProgramRun twice = run_in(folder, "mechanism jansen --sweep 0:10:5 --svg a.svg --animate ./a.svg");
  CHECK(twice.exit_code == 2);
  CHECK_THAT(twice.err, Contains("written twice"));
  CHECK_FALSE(fs::exists(folder + "/a.svg"));
  fs::remove_all(folder);

  // An empty --out would put the lab's folder at the file-system root.
  require_rejected_writing_nothing("lab gauss --out ''", "--out: must name a folder");
  require_rejected_writing_nothing("fit --foot-path upper --degree 2 --chart \"it's.svg\"", "must not contain quotes");
}

TEST_CASE("At a terminal, q at a --step pause stops the run and reports what ran", "[cli][options][step][tty]") {
  if (!have_script()) {
    WARN("util-linux `script` is not installed: the terminal half of --step is not tested here");
    return;
  }
  // Newton on Powell's singular function takes many iterations: Enter twice, then q.
  const ProgramRun solve = run_at_terminal("sleep 0.3; printf '\\n'; sleep 0.2; printf '\\n'; sleep 0.2; printf 'q\\n'",
                                           "solve nonlinear --problem powell-singular --method newton --step --format json");
  INFO(solve.out);
  CHECK(solve.exit_code == 1);
  CHECK_THAT(solve.out, Contains("\"status\": \"stopped_by_user\"") && Contains("\"steps_done\": 3"));
  CHECK_THAT(solve.out, Contains("Enter: next step; q, Enter: stop here"));

  // A lab stopped after its first step still writes report.html with that step.
  const std::string folder = temporary_folder();
  const ProgramRun lab = run_at_terminal("sleep 0.3; printf 'q\\n'", "lab inverse2x2 --step --out " + folder);
  INFO(lab.out);
  CHECK(lab.exit_code == 1);
  const std::string html = file_text(folder + "/lab-inverse2x2/report.html");
  CHECK_THAT(html, Contains("Step 1:") && Contains("Stopped with q after step 1"));
  CHECK(html.find("Step 2:") == std::string::npos);
  fs::remove_all(folder);

  // Pauses are not counted in the solve time: two pauses of ~0.7 s, a solve of microseconds.
  const ProgramRun timed = run_at_terminal("sleep 0.7; printf '\\n'; sleep 0.7; printf '\\n'",
                                           "solve nonlinear --problem rosenbrock --method newton --step --format json");
  CHECK(timed.exit_code == 0);
  std::smatch match;
  REQUIRE(std::regex_search(timed.out, match, std::regex("\"time_s\": ([0-9.e+-]+)")));
  CHECK(std::stod(match[1]) < 0.3);
}
