// The starters of `exercise init`: their files and contents in each language, and the Python (and,
// where octave-cli is installed, the Octave) starter run through the real checker on a tiny
// exercise: as generated every check fails with "not implemented"; with the stub written, all pass.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "exercises/checker.hpp"
#include "exercises/child_session.hpp"
#include "exercises/starters.hpp"
#include "tiny_exercise.hpp"

using namespace numlab::exercises;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const StarterFile& file_named(const std::vector<StarterFile>& files, const std::string& path) {
  for (const StarterFile& file : files)
    if (file.path == path) return file;
  FAIL("no starter file " << path);
  throw std::logic_error("unreachable");
}

std::vector<std::string> paths(const std::vector<StarterFile>& files) {
  std::vector<std::string> out;
  for (const StarterFile& file : files) out.push_back(file.path);
  return out;
}

std::string fresh_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("numlab-starter-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  return folder.string();
}

bool on_path(const std::string& program) { return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0; }

// Runs the exercise's battery through the real sandboxed child: `command`, its file arguments in `folder`.
std::vector<CheckResult> check_starter(const std::string& folder, std::vector<std::string> command,
                                       const Exercise& exercise = numlab::test::tiny_exercise()) {
  for (std::string& word : command)
    if (word.ends_with(".py") || word.ends_with(".m")) word = folder + "/" + word;
  ChildSession session(exercise.name, command, 30.0);
  return run_checks(exercise, session);
}

void require_all_fail_not_implemented(const std::vector<CheckResult>& results, std::size_t checks = 3) {
  REQUIRE(results.size() == checks);
  for (const CheckResult& result : results) {
    INFO(result.name << ": " << to_string(result.status) << ": " << result.message);
    CHECK(result.status == CheckStatus::fail);
    CHECK_THAT(result.message, StartsWith("your program replied with an error:") && Contains("not implemented"));
  }
}

void require_all_pass(const std::vector<CheckResult>& results) {
  REQUIRE(results.size() == 3);
  for (const CheckResult& result : results) {
    INFO(result.name << ": " << result.message);
    CHECK(result.status == CheckStatus::pass);
  }
}

}  // namespace

TEST_CASE("The language is python, cpp or octave, and any other is named in the error", "[starters]") {
  CHECK(parse_language("python") == Language::python);
  CHECK(parse_language("cpp") == Language::cpp);
  CHECK(parse_language("octave") == Language::octave);
  CHECK_THROWS_WITH(parse_language("matlab"), "exercise init: --lang must be python, cpp or octave, not 'matlab'");
  CHECK_THROWS_AS(parse_language(""), std::invalid_argument);
}

TEST_CASE("Each starter has TASK.md with the exact check command, and the program with the stub", "[starters]") {
  const Exercise exercise = numlab::test::tiny_exercise();

  const auto python = starter_files(exercise, Language::python);
  CHECK(paths(python) == std::vector<std::string>{"TASK.md", "solution.py"});
  const StarterFile& task = file_named(python, "TASK.md");
  CHECK_THAT(task.contents, StartsWith(exercise.task) && Contains("## How to check") &&
                                Contains("numlab exercise check tiny-sum -- python3 solution.py"));
  const StarterFile& py = file_named(python, "solution.py");
  CHECK(py.executable);
  CHECK_THAT(py.contents, StartsWith("#!/usr/bin/env python3") && Contains("import numpy as np") &&
                              Contains("def solve(request):\n    raise NotImplementedError(\"not implemented") &&
                              Contains("flush=True") && Contains("\"error\""));

  const auto cpp = starter_files(exercise, Language::cpp);
  CHECK(paths(cpp) == std::vector<std::string>{"TASK.md", "CMakeLists.txt", "solution.cpp"});
  CHECK_THAT(file_named(cpp, "TASK.md").contents,
             Contains("cmake -S . -B build") && Contains("cmake --build build && numlab exercise check tiny-sum -- build/solution"));
  const std::string& lists = file_named(cpp, "CMakeLists.txt").contents;
  CHECK_THAT(lists, Contains("cmake_minimum_required(VERSION 3.16)") && Contains("find_package(numlab REQUIRED)") &&
                        Contains("add_executable(solution solution.cpp)") &&
                        Contains("target_link_libraries(solution PRIVATE numlab::exercise_protocol)") &&
                        Contains("project(numlab_exercise_tiny_sum"));
  const std::string& solution = file_named(cpp, "solution.cpp").contents;
  CHECK_THAT(solution, Contains("#include <numlab/exercise_protocol.hpp>") &&
                           Contains("json solve(const json& request) {\n  throw std::runtime_error(\"not implemented") &&
                           Contains("int main() { return numlab::exercise::serve(solve); }"));
  CHECK_FALSE(file_named(cpp, "solution.cpp").executable);

  const auto octave = starter_files(exercise, Language::octave);
  CHECK(paths(octave) == std::vector<std::string>{"TASK.md", "solution.m"});
  CHECK_THAT(file_named(octave, "TASK.md").contents,
             Contains("numlab exercise check tiny-sum -- octave-cli --no-gui --quiet solution.m") &&
                 Contains("apt-get install octave"));
  const std::string& m = file_named(octave, "solution.m").contents;
  CHECK_THAT(m, Contains("\n1;\n") && Contains("function reply = solve(request)\n  error('not implemented") &&
                    Contains("input('', 's')") && Contains("jsondecode") && Contains("jsonencode") &&
                    Contains("fflush(stdout)") && Contains("'error', err.message"));
}

TEST_CASE("A stub comes re-indented as the body, whatever indentation it was written with", "[starters]") {
  Exercise exercise = numlab::test::tiny_exercise();
  exercise.stubs.python = "        x = 1\n\n        raise NotImplementedError(\"not implemented\")\n\n";
  const std::string py = file_named(starter_files(exercise, Language::python), "solution.py").contents;
  CHECK_THAT(py, Contains("def solve(request):\n    x = 1\n\n    raise NotImplementedError(\"not implemented\")\n\n\ndef"));
}

TEST_CASE("The Python starter, as generated, fails every check with 'not implemented', and solved it passes",
          "[starters][python]") {
  const Exercise exercise = numlab::test::tiny_exercise();
  const std::string folder = fresh_folder("python");
  write_starter_files(folder, starter_files(exercise, Language::python));
  CHECK((std::filesystem::status(folder + "/solution.py").permissions() & std::filesystem::perms::owner_exec) !=
        std::filesystem::perms::none);
  require_all_fail_not_implemented(check_starter(folder, {NUMLAB_PYTHON3, "solution.py"}));

  // The loop sends numpy arrays and numpy numbers as JSON: the solved starter passes.
  Exercise solved = exercise;
  solved.stubs.python = numlab::test::tiny_solutions().python;
  write_starter_files(folder, starter_files(solved, Language::python));
  require_all_pass(check_starter(folder, {NUMLAB_PYTHON3, "solution.py"}));
  std::filesystem::remove_all(folder);
}

TEST_CASE("The Octave starter, as generated, fails every check with 'not implemented', and solved it passes",
          "[starters][octave]") {
  if (!on_path("octave-cli")) {
    WARN("SKIPPED: octave-cli is not on PATH (apt-get install octave); the Octave starter is not run");
    return;
  }
  const Exercise exercise = numlab::test::tiny_exercise();
  const std::string folder = fresh_folder("octave");
  write_starter_files(folder, starter_files(exercise, Language::octave));
  const std::vector<std::string> octave = {"octave-cli", "--no-gui", "--quiet", "solution.m"};
  require_all_fail_not_implemented(check_starter(folder, octave));
  Exercise solved = exercise;
  solved.stubs.octave = numlab::test::tiny_solutions().octave;
  write_starter_files(folder, starter_files(solved, Language::octave));
  require_all_pass(check_starter(folder, octave));
  std::filesystem::remove_all(folder);
}

TEST_CASE("The Octave starter sends every digit: tiny numbers, vectors as lists, one-entry lists as cells",
          "[starters][octave]") {
  if (!on_path("octave-cli")) {
    WARN("SKIPPED: octave-cli is not on PATH (apt-get install octave); the Octave starter is not run");
    return;
  }
  // Octave 7's jsonencode writes 1e-170 and 1.5e-16 as 0: the starter's to_json must not.
  Exercise exercise = numlab::test::tiny_exercise();
  exercise.stubs.octave =
      "reply = struct('tiny', [1e-170, 1.5e-16], 'third', 1/3, 'column', [1; 2], 'rows', [1, 2; 3, 4]);\n"
      "reply.one = num2cell(7);\n"
      "reply.steps = num2cell(struct('a', {5}));\n"
      "reply.status = 'converged';\n"
      "reply.flag = true;\n";
  const std::string folder = fresh_folder("octave-json");
  write_starter_files(folder, starter_files(exercise, Language::octave));
  ChildSession session(exercise.name, {"octave-cli", "--no-gui", "--quiet", folder + "/solution.m"}, 30.0);
  const nlohmann::json reply = session.ask({{"v", {1.0}}});
  CHECK(reply.at("tiny") == nlohmann::json({1e-170, 1.5e-16}));
  CHECK(reply.at("third").get<double>() == 1.0 / 3.0);
  CHECK(reply.at("column") == nlohmann::json({1, 2}));
  CHECK(reply.at("rows") == nlohmann::json({{1, 2}, {3, 4}}));
  CHECK(reply.at("one") == nlohmann::json::array({7}));
  CHECK(reply.at("steps") == nlohmann::json::array({{{"a", 5}}}));
  CHECK(reply.at("status") == "converged");
  CHECK(reply.at("flag") == true);
  session.finish();
  std::filesystem::remove_all(folder);
}

TEST_CASE("Every exercise's Python and Octave starters, as generated, fail every check with 'not implemented'",
          "[starters][python][octave]") {
  const bool octave = on_path("octave-cli");
  if (!octave) WARN("octave-cli is not on PATH (apt-get install octave): only the Python starters are run");
  for (const Exercise& exercise : all_exercises()) {
    INFO(exercise.name);
    const std::size_t checks = exercise.battery(Variant()).size();
    const std::string folder = fresh_folder(exercise.name);
    write_starter_files(folder, starter_files(exercise, Language::python));
    require_all_fail_not_implemented(check_starter(folder, {NUMLAB_PYTHON3, "solution.py"}, exercise), checks);
    if (octave) {
      write_starter_files(folder, starter_files(exercise, Language::octave));
      require_all_fail_not_implemented(
          check_starter(folder, {"octave-cli", "--no-gui", "--quiet", "solution.m"}, exercise), checks);
    }
    std::filesystem::remove_all(folder);
  }
}
