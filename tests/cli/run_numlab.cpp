#include "run_numlab.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace numlab::test {

std::string read_all(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

std::string temporary_folder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "numlab-test-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

std::string temporary_file(const std::string& name, const std::string& contents) {
  const std::string path = temporary_folder() + "/" + name;
  std::ofstream(path) << contents;
  return path;
}

ProgramRun run_numlab(const std::string& arguments) {
  const std::string folder = temporary_folder();
  const std::string command = std::string(NUMLAB_BINARY) + " " + arguments + " </dev/null >" + folder + "/out 2>" +
                              folder + "/err";
  const int status = std::system(command.c_str());
  ProgramRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(folder + "/out"), read_all(folder + "/err")};
  std::filesystem::remove_all(folder);
  return run;
}

nlohmann::json run_json(const std::string& command, const std::string& arguments, int expected_exit) {
  const ProgramRun run = run_numlab(command + " " + arguments + " --format json");
  INFO("numlab " << command << " " << arguments << "\nstderr: " << run.err);
  REQUIRE(run.exit_code == expected_exit);
  return nlohmann::json::parse(run.out);
}

void require_bad_input(const std::string& arguments, const std::string& named) {
  const ProgramRun run = run_numlab(arguments);
  INFO("numlab " << arguments << "\nstderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Catch::Matchers::StartsWith("numlab: error:") && Catch::Matchers::Contains(named));
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
}

}  // namespace numlab::test
