#include "commands/exercise_command.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <stdexcept>
#include <sys/stat.h>

#include "exercises/checker.hpp"
#include "exercises/child_session.hpp"
#include "exercises/exercise.hpp"
#include "exercises/results.hpp"
#include "exercises/starters.hpp"

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;
using exercises::CheckStatus;

constexpr double max_timeout_seconds = 3600.0;

std::string timeout_problem(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && end == text.c_str() + text.size();
  if (number && std::isfinite(value) && value > 0.0 && value <= max_timeout_seconds) return "";
  return fmt::format("must be a number of seconds above 0 and at most {:g}, got '{}'", max_timeout_seconds, text);
}

// "mydir/" and "mydir//" name the folder "mydir" (whose parent is ".", not "mydir"); "/" stays "/".
fs::path without_trailing_slashes(std::string folder) {
  while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
  return folder;
}

// The starter's files go into `folder`: a new folder is made whole (written beside it, then
// renamed into place); in an existing folder no file is overwritten.
void write_starter(const std::string& folder, const std::vector<exercises::StarterFile>& files) {
  if (folder.empty()) throw std::invalid_argument("exercise init: the folder name is empty");
  const fs::path target = without_trailing_slashes(folder);
  std::error_code error;
  const bool exists = fs::exists(target, error);
  if (exists && !fs::is_directory(target, error)) {
    throw std::invalid_argument("exercise init: '" + folder + "' exists and is not a folder");
  }
  if (exists) {
    for (const auto& file : files) {
      if (fs::exists(target / file.path, error)) {
        throw std::invalid_argument("exercise init: '" + (target / file.path).string() +
                                    "' exists already (nothing was written)");
      }
    }
  }
  fs::path staging = target;
  if (!exists) {
    const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, error)) {
      throw std::invalid_argument("exercise init: the folder '" + parent.string() + "' does not exist");
    }
    std::string pattern = (parent / ("." + target.filename().string() + ".partial-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::invalid_argument("exercise init: cannot make a folder beside '" + folder + "'");
    }
    staging = pattern;
  }
  try {
    for (const auto& file : files) {
      const fs::path path = staging / file.path;
      fs::create_directories(path.parent_path());
      write_file_atomically(path.string(), file.contents);
      if (file.executable) ::chmod(path.c_str(), 0755);
    }
    if (!exists) fs::rename(staging, target);
  } catch (...) {
    if (!exists) fs::remove_all(staging, error);
    throw;
  }
}

int exit_code_for(const std::vector<exercises::CheckResult>& results) {
  for (const auto& result : results) {
    if (result.status != CheckStatus::pass) return exit_method_failed;
  }
  return exit_success;
}

std::string shell_words(const std::vector<std::string>& words) {
  std::string line;
  for (const auto& word : words) line += (line.empty() ? "" : " ") + word;
  return line;
}

}  // namespace

ExerciseCommand::ExerciseCommand(CLI::App& app) {
  command_ = app.add_subcommand("exercise", "Check a student's own solver against the references (docs/exercises.md)");
  command_->require_subcommand(0, 1);
  list_ = command_->add_subcommand("list", "The exercises, one line each");
  show_ = command_->add_subcommand("show", "An exercise's task: what to write, the fields, the equations, hints");
  show_->add_option("NAME", name_, "The exercise")->required();
  init_ = command_->add_subcommand("init", "Write a starter (TASK.md and a stub that speaks the protocol) into DIR");
  init_->add_option("NAME", name_, "The exercise")->required();
  init_->add_option("DIR", folder_, "The folder for the starter (made if missing; no file in it is overwritten)")
      ->required();
  init_->add_option("--lang", language_, "python (default), cpp or octave");
  check_ = command_->add_subcommand("check", "Run COMMAND as a child process and check its replies");
  check_->add_option("NAME", name_, "The exercise")->required();
  check_->add_option("--timeout", timeout_seconds_, "Seconds allowed per request (default 10)")
      ->check(CLI::Validator(timeout_problem, "S"));
  check_->add_option("COMMAND", program_, "The student's program and its arguments, after --")->required();
  add_common_options(*check_, common_);
}

int ExerciseCommand::run() const {
  if (list_->parsed()) return list();
  if (show_->parsed()) return show();
  if (init_->parsed()) return init();
  if (check_->parsed()) return check();
  throw std::invalid_argument("exercise: say what to do: list, show NAME, init NAME DIR or check NAME -- COMMAND");
}

int ExerciseCommand::list() const {
  for (const auto& exercise : exercises::all_exercises()) {
    std::cout << fmt::format("{:<18} {}\n", exercise.name, exercise.summary);
  }
  return exit_success;
}

int ExerciseCommand::show() const {
  std::cout << exercises::find_exercise(name_).task;
  return exit_success;
}

int ExerciseCommand::init() const {
  // 1. Everything checked before anything is written.
  const auto& exercise = exercises::find_exercise(name_);
  const auto language = exercises::parse_language(language_);
  const auto files = exercises::starter_files(exercise, language);
  // 2. The files, whole or not at all.
  write_starter(folder_, files);
  const std::string folder = without_trailing_slashes(folder_).string();
  std::cout << fmt::format("Wrote the {} starter for '{}' in {}{}:\n", language_, exercise.name, folder,
                           folder.ends_with('/') ? "" : "/");
  for (const auto& file : files) std::cout << "  " << file.path << '\n';
  std::cout << "Read TASK.md; it ends with the command that checks your solution.\n";
  return exit_success;
}

int ExerciseCommand::check() const {
  // 1. Everything the user gave, checked before the program is started.
  const CommonOptions common = checked_common_options(common_, "exercise check");
  const auto& exercise = exercises::find_exercise(name_);
  std::vector<PlannedFile> outputs;
  if (given(common, "--out")) {
    outputs = {{(fs::path(common.out_dir) / "report.html").string(), "--out"},
               {(fs::path(common.out_dir) / "results.json").string(), "--out"}};
    check_outputs(outputs, {});
  }
  // 2. The program, started in its sandbox (a command that cannot start is bad input).
  exercises::ChildSession session(exercise.name, program_, timeout_seconds_);
  // 3. The battery.
  const auto results = exercises::run_checks(exercise, session);
  session.finish();
  // 4. The verdicts: on stdout, and as files with --out.
  const auto json = exercises::results_json(results);
  if (common.format == Format::json) {
    std::cout << json.dump(2) << '\n';
  } else {
    std::cout << exercises::results_text(exercise, results);
  }
  if (!outputs.empty()) {
    ensure_directory(common.out_dir);
    write_file_atomically(outputs[0].path, exercises::results_html(exercise, results, shell_words(program_)));
    write_file_atomically(outputs[1].path, json.dump(2) + "\n");
  }
  return exit_code_for(results);
}

}  // namespace numlab::cli
