// `numlab exercise` as a student runs it (docs/exercises.md): the list, the task, starters that
// never overwrite a file, and bad input (an unknown exercise, a program that cannot start, flags
// that do not apply) as one line and exit 2. The verdicts themselves are tested in tests/exercises/.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_numlab.hpp"

using Catch::Matchers::Contains;
using numlab::test::ProgramRun;
using numlab::test::read_all;
using numlab::test::require_bad_input;
using numlab::test::run_numlab;
using numlab::test::temporary_folder;

namespace {
namespace fs = std::filesystem;
}  // namespace

TEST_CASE("exercise list names the seven exercises of the contract and jansen10-jacobian, one line each", "[exercise]") {
  const ProgramRun run = run_numlab("exercise list");
  REQUIRE(run.exit_code == 0);
  for (const char* name : {"gepp", "gauss-seidel", "inverse2x2", "polyfit", "jansen-jacobian", "jansen10-jacobian",
                           "jansen-newton", "mustang-newton"}) {
    CHECK_THAT(run.out, Contains(std::string("\n") + name + " ") || Catch::Matchers::StartsWith(std::string(name) + " "));
  }
}

TEST_CASE("exercise show prints the task with the request and reply fields", "[exercise]") {
  const ProgramRun run = run_numlab("exercise show gepp");
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("pivot_row"));
  CHECK_THAT(run.out, Contains("singular"));
}

TEST_CASE("exercise init writes a starter whole and never overwrites a file", "[exercise]") {
  const std::string folder = temporary_folder();
  const std::string target = folder + "/mine";
  const ProgramRun run = run_numlab("exercise init gepp " + target);
  REQUIRE(run.exit_code == 0);
  CHECK(fs::exists(target + "/TASK.md"));
  CHECK(fs::exists(target + "/solution.py"));
  std::ofstream(target + "/solution.py") << "my own work\n";
  require_bad_input("exercise init gepp " + target, "exists already");
  CHECK(read_all(target + "/solution.py") == "my own work\n");
  // No hidden half-made folder is left beside it either.
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++entries;
  CHECK(entries == 1);
  fs::remove_all(folder);
}

TEST_CASE("exercise: bad input is one line and exit 2", "[exercise]") {
  require_bad_input("exercise show no-such-exercise", "unknown exercise 'no-such-exercise'");
  require_bad_input("exercise check no-such-exercise -- python3 x.py", "unknown exercise");
  require_bad_input("exercise check gepp -- /no/such/program", "cannot run '/no/such/program'");
  require_bad_input("exercise check gepp -- no-such-program-on-path", "cannot run 'no-such-program-on-path'");
  require_bad_input("exercise check gepp --timeout 0 -- python3", "--timeout");
  require_bad_input("exercise check gepp --timeout nan -- python3", "--timeout");
  // check takes only its own options: the shared --trace, --step, --tol, --max-iter and csv are unknown to it.
  require_bad_input("exercise check gepp --format csv -- python3", "--format: must be text or json, got 'csv'");
  require_bad_input("exercise check gepp --trace -- python3", "unexpected arguments '--trace'");
  require_bad_input("exercise replay /no/such/file.jsonl -- python3", "/no/such/file.jsonl: cannot be read");
  require_bad_input("exercise init gepp " + temporary_folder() + "/x --lang fortran", "--lang");
  require_bad_input("exercise init gepp /no/such/parent/x", "does not exist");
  require_bad_input("exercise check gepp", "COMMAND");
  require_bad_input("exercise", "exercise");
}

TEST_CASE("exercise check --help lists only the options check honours, and says what --out writes", "[exercise]") {
  const ProgramRun run = run_numlab("exercise check --help");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("--format") && Contains("text|json") && Contains("--timeout") && Contains("--out"));
  CHECK_THAT(run.out, Contains("DIR/report.html, DIR/results.json") && Contains("DIR/replay/NN-CHECK.jsonl"));
  for (const char* refused : {"--trace", "--step", "--tol", "--max-iter", "csv"}) {
    INFO(refused);
    CHECK(run.out.find(refused) == std::string::npos);
  }
}

TEST_CASE("exercise init takes --language as the long form of --lang", "[exercise]") {
  const std::string folder = temporary_folder();
  const ProgramRun run = run_numlab("exercise init gepp " + folder + "/s --language cpp");
  CHECK(run.exit_code == 0);
  CHECK(fs::exists(folder + "/s/solution.cpp"));
  require_bad_input("exercise init gepp " + folder + "/t --language fortran", "--lang");
  fs::remove_all(folder);
}

TEST_CASE("exercise check --out writes report.html, results.json and a replay per failing check", "[exercise]") {
  const std::string folder = temporary_folder();
  const std::string starter = folder + "/starter";
  REQUIRE(run_numlab("exercise init inverse2x2 " + starter).exit_code == 0);
  const ProgramRun run = run_numlab("exercise check inverse2x2 --out " + folder + "/verdict -- " NUMLAB_PYTHON3 " " + starter +
                                    "/solution.py");
  // The starter as generated: every check fails honestly, none errs.
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.out, Contains("not implemented"));
  const nlohmann::json results = nlohmann::json::parse(read_all(folder + "/verdict/results.json"));
  CHECK(results["version"] == 3);
  CHECK(results["status"] == "fail");
  for (const auto& test : results["tests"]) CHECK(test["status"] == "fail");
  CHECK_THAT(read_all(folder + "/verdict/report.html"), Contains("<html"));
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder + "/verdict")) ++entries;
  CHECK(entries == 3);
  // One replay file per check (each fails), named by its place and name.
  int replays = 0;
  for (const auto& entry : fs::directory_iterator(folder + "/verdict/replay")) {
    CHECK(entry.path().extension() == ".jsonl");
    ++replays;
  }
  CHECK(replays == static_cast<int>(results["tests"].size()));
  CHECK_THAT(run.out, Contains("Replay it: numlab exercise replay " + folder + "/verdict/replay/01-"));
  fs::remove_all(folder);
}
