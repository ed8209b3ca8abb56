#pragma once
// Runs the numlab program as a user would (stdin from /dev/null, so --step never blocks) and
// captures its exit code, stdout and stderr.

#include <nlohmann/json.hpp>
#include <string>

namespace numlab::test {

struct ProgramRun {
  int exit_code;
  std::string out;
  std::string err;
};

// `arguments` is appended to the program path as shell words.
ProgramRun run_numlab(const std::string& arguments);

// Runs `numlab COMMAND ARGUMENTS --format json`, requires the exit code, and parses stdout.
nlohmann::json run_json(const std::string& command, const std::string& arguments, int expected_exit);

// Bad input: requires exit 2, nothing on stdout, and exactly one line on stderr that starts
// "numlab: error:" and contains `named`.
void require_bad_input(const std::string& arguments, const std::string& named);

// The whole contents of a file ("" when it cannot be read).
std::string read_all(const std::string& path);

// A fresh temporary folder for files a test writes.
std::string temporary_folder();

// Writes `contents` to a file in a temporary folder and returns its path.
std::string temporary_file(const std::string& name, const std::string& contents);

}  // namespace numlab::test
