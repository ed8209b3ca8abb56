#include "commands/exercise_command.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <stdexcept>
#include <sys/stat.h>

#include "exercises/checker.hpp"
#include "exercises/command_line.hpp"
#include "exercises/child_session.hpp"
#include "exercises/exercise.hpp"
#include "exercises/replay.hpp"
#include "exercises/results.hpp"
#include "exercises/starters.hpp"
#include "exercises/trace_page.hpp"
#include "commands/exercise_model.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/printable_text.hpp"

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;
using exercises::CheckStatus;
using exercises::shell_word;
using exercises::shell_words;

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

std::string out_dir_problem(const std::string& text) {
  if (text.empty()) return "must name a folder, got an empty name";
  const bool odd = text.find('\'') != std::string::npos || printable(text) != text;
  return odd ? "'" + text + "': a folder name without quotes, control or invisible characters, please" : "";
}

// The failing checks' replay files (DIR/replay/NN-CHECK.jsonl), each result told the command that
// replays it. A check without a request (one not run) has none.
std::vector<std::pair<std::string, std::string>> plan_replays(std::vector<exercises::CheckResult>& results,
                                                              const fs::path& out_dir,
                                                              const std::vector<std::string>& program,
                                                              const exercises::Variant& variant) {
  std::vector<std::pair<std::string, std::string>> files;  // name, contents
  for (std::size_t k = 0; k < results.size(); ++k) {
    auto& result = results[k];
    if (result.status == CheckStatus::pass || result.exchanges.empty()) continue;
    const std::string name = exercises::replay_file_name(static_cast<int>(k) + 1, result.name);
    result.replay = "numlab exercise replay " + shell_word((out_dir / "replay" / name).string()) + " -- " +
                    shell_words(program);
    files.emplace_back(name, exercises::replay_lines(result, variant));
  }
  return files;
}

// DIR/replay holds this run's failures only: made whole beside it, then put in place of the last
// run's (which is removed), so no replay of a check that now passes is left behind.
void write_replays(const fs::path& out_dir, const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path target = out_dir / "replay";
  std::error_code error;
  if (fs::exists(target, error) && !fs::is_directory(target, error)) {
    throw std::invalid_argument("exercise check: '" + target.string() + "' exists and is not a folder");
  }
  if (files.empty() && !fs::exists(target, error)) return;
  std::string pattern = (out_dir / ".replay.partial-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::invalid_argument("exercise check: cannot make a folder in '" + out_dir.string() + "'");
  }
  const fs::path staging = pattern;
  try {
    for (const auto& [name, contents] : files) write_file_atomically((staging / name).string(), contents);
    if (fs::exists(target, error)) {
      std::string old = (out_dir / ".replay.old-XXXXXX").string();
      if (::mkdtemp(old.data()) == nullptr) throw std::invalid_argument("cannot make a folder");
      fs::rename(target, fs::path(old) / "replay");
      fs::remove_all(old, error);
    }
    fs::rename(staging, target);
  } catch (const std::exception& failure) {
    fs::remove_all(staging, error);
    throw std::invalid_argument("exercise check: cannot write '" + target.string() + "': " + failure.what());
  }
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
  init_->add_option("--lang,--language", language_, "python (default), cpp or octave");
  const char* const variant_help =
      "A variant ID (any non-empty string, e.g. a student number): every random matrix, right-hand side, start and "
      "crank angle of the checks is drawn from it; the same ID gives the same requests";
  variant_options_.push_back(init_->add_option("--variant", variant_, std::string(variant_help) +
                                                                          "; TASK.md names it and its check command"));
  init_->add_option("--model", model_,
                    "linkage only: the linkage description FILE.toml (copied into DIR as model.toml) or a shipped "
                    "model's NAME (numlab models)");
  check_ = command_->add_subcommand("check", "Run COMMAND as a child process and check its replies");
  check_->add_option("NAME", name_, "The exercise")->required();
  check_->add_option_function<std::string>(
            "--format", [this](const std::string& text) { json_ = text == "json"; },
            "On stdout: text (default), or json (results.json's contents)")
      ->check(CLI::Validator(
          [](std::string& text) {
            return text == "text" || text == "json" ? std::string() : "must be text or json, got '" + text + "'";
          },
          "text|json"));
  check_->add_option("--out", out_dir_,
                     "Also write, after the checks ran, DIR/report.html, DIR/results.json and, for each check that "
                     "does not pass, DIR/replay/NN-CHECK.jsonl (its requests; the report gives the command that "
                     "replays it). Without --out nothing is written")
      ->check(CLI::Validator(out_dir_problem, "DIR"));
  check_->add_option("--timeout", timeout_seconds_, "Seconds allowed per request (default 10)")
      ->check(CLI::Validator(timeout_problem, "S"));
  variant_options_.push_back(check_->add_option(
      "--variant", variant_, std::string(variant_help) + "; the reports and results.json name it"));
  check_->add_option("--model", model_,
                     "linkage only (and required there): the linkage description FILE.toml or a shipped model's NAME");
  check_->add_option("COMMAND", program_, "The student's program and its arguments, after --")->required();
  replay_ = command_->add_subcommand(
      "replay", "Send a failing check's requests (FILE, from check --out) to COMMAND again; show each reply beside "
                "numlab's; exit 1 while they differ beyond the check's tolerance");
  replay_->add_option("FILE", replay_file_, "DIR/replay/NN-CHECK.jsonl, as exercise check --out DIR wrote it")
      ->required();
  replay_->add_option("--timeout", timeout_seconds_, "Seconds allowed per request (default 10)")
      ->check(CLI::Validator(timeout_problem, "S"));
  replay_->add_option("--model", model_, "linkage only (and required there): the --model the check was run with");
  replay_->add_option("COMMAND", program_, "The student's program and its arguments, after --")->required();
}

int ExerciseCommand::run() const {
  if (list_->parsed()) return list();
  if (show_->parsed()) return show();
  if (init_->parsed()) return init();
  if (check_->parsed()) return check();
  if (replay_->parsed()) return replay();
  throw std::invalid_argument(
      "exercise: say what to do: list, show NAME, init NAME DIR, check NAME -- COMMAND or replay FILE -- COMMAND");
}

exercises::Variant ExerciseCommand::variant() const {
  for (const CLI::Option* option : variant_options_) {
    if (option->count() > 0) {
      if (const std::string problem = exercises::variant_id_problem(variant_); !problem.empty()) {
        throw std::invalid_argument("exercise: --variant: " + problem);
      }
      return exercises::Variant(variant_);
    }
  }
  return {};
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
  // 1. Everything checked before anything is written. A linkage file is copied into DIR as model.toml.
  std::error_code error;
  const bool model_file = !model_.empty() && fs::is_regular_file(model_, error);
  const NamedExercise named = exercise_named(name_, model_, "init", model_file ? "model.toml" : "");
  const auto& exercise = named.exercise;
  const auto language = exercises::parse_language(language_);
  auto files = exercises::starter_files(exercise, language, variant());
  if (!named.model_file.empty() && !named.model_shipped) files.push_back({"model.toml", linalg::read_text_file(named.model_file), false});
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
  const NamedExercise named = exercise_named(name_, model_, "check");
  const auto& exercise = named.exercise;
  const exercises::Variant variant = this->variant();
  std::vector<PlannedFile> outputs;
  const bool out = !out_dir_.empty();
  if (out) {
    outputs = {{(fs::path(out_dir_) / "report.html").string(), "--out"},
               {(fs::path(out_dir_) / "results.json").string(), "--out"},
               {(fs::path(out_dir_) / "replay" / "01-check.jsonl").string(), "--out"},
               {(fs::path(out_dir_) / "trace.html").string(), "--out"}};
    check_outputs(outputs, {});
  }
  // 2. The program, started in its sandbox (a command that cannot start is bad input).
  exercises::ChildSession session(exercise.name, program_, timeout_seconds_);
  // 3. The battery.
  auto results = exercises::run_checks(exercise, session, variant);
  session.finish();
  // 4. The verdicts: on stdout, and as files with --out (with a replay file per failing check).
  const auto replays = out ? plan_replays(results, out_dir_, program_, variant)
                           : std::vector<std::pair<std::string, std::string>>{};
  for (auto& result : results) {  // the linkage exercise's replay needs its --model too
    const std::size_t end = result.replay.find(" -- ");
    if (end != std::string::npos && !exercise.arguments.empty()) result.replay.insert(end, " " + shell_words(exercise.arguments));
  }
  const auto json = exercises::results_json(results, "", variant);
  if (json_) {
    std::cout << json.dump(2) << '\n';
  } else {
    std::cout << exercises::results_text(exercise, results, variant);
  }
  if (out) {
    ensure_directory(out_dir_);
    // trace.html only for a failing trace check; one a run before left is removed (it would mislead).
    // The pages and results.json all in place, or none (a full disk): the old trace.html goes after.
    FileBatch files;
    const exercises::CheckResult* traced = exercises::failing_trace_check(results);
    if (traced != nullptr) files.add(outputs[3].path, exercises::trace_page_html(exercise, *traced, variant));
    files.add(outputs[0].path, exercises::results_html(exercise, results, shell_words(program_), variant));
    files.add(outputs[1].path, json.dump(2) + "\n");
    files.commit();
    if (traced == nullptr) {
      std::error_code ignored;
      fs::remove(outputs[3].path, ignored);
    }
    write_replays(out_dir_, replays);
  }
  return exit_code_for(results);
}

int ExerciseCommand::replay() const {
  // 1. The file, its exercise and its check, before the program is started.
  const exercises::ReplayFile file = exercises::read_replay_file(replay_file_);
  const NamedExercise named = exercise_named(file.exercise, model_, "replay");
  const auto& exercise = named.exercise;
  const exercises::Check check = exercises::find_check(exercise, file.check, file.variant);
  // 2. The same check, through the same sandbox as `exercise check`.
  exercises::ChildSession session(exercise.name, program_, timeout_seconds_);
  const exercises::CheckResult result = exercises::run_check(exercise, check, session);
  session.finish();
  // 3. Request by request, the program's reply beside numlab's, then the verdict.
  std::cout << exercises::replay_text(result, exercises::requests_mismatch(file, result));
  return result.status == CheckStatus::pass ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
