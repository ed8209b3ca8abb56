#include "commands/exercise_grade.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "exercises/child_process.hpp"
#include "exercises/exercise.hpp"
#include "exercises/grading.hpp"
#include "commands/exercise_model.hpp"
#include "exercises/results.hpp"
#include "exercises/trace_page.hpp"
#include "numlab/printable_text.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

std::string seconds_problem(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && end == text.c_str() + text.size();
  if (number && std::isfinite(value) && value > 0.0 && value <= 3600.0) return "";
  return fmt::format("must be a number of seconds above 0 and at most 3600, got '{}'", text);
}

std::string folder_problem(const std::string& text) {
  if (text.empty()) return "must name a folder, got an empty name";
  const bool odd = text.find('\'') != std::string::npos || printable(text) != text;
  return odd ? "'" + text + "': a folder name without quotes, control or invisible characters, please" : "";
}

int default_jobs() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

}  // namespace

ExerciseGradeCommand::ExerciseGradeCommand(CLI::App& exercise) {
  command_ = exercise.add_subcommand(
      "grade", "Check every sub-folder of DIR (one student's submission each, as exercise init lays it out) as "
               "exercise check does; write OUT/STUDENT/report.html and results.json and OUT/gradebook.csv");
  command_->add_option("NAME", name_, "The exercise")->required();
  command_->add_option("--submissions", submissions_, "The folder of submissions: one sub-folder per student")
      ->check(CLI::Validator(folder_problem, "DIR"));
  command_->add_option("--out", out_dir_,
                       "The folder for gradebook.csv and each student's report.html, results.json (and build/, "
                       "build.log for C++); refused when it holds a gradebook.csv or a student's folder already")
      ->required()
      ->check(CLI::Validator(folder_problem, "OUT"));
  command_->add_option("--model", model_,
                       "linkage only (and required there): the linkage description FILE.toml or a shipped model's NAME");
  variant_option_ = command_->add_option(
      "--variant", variant_,
      "Every student gets this variant ID (the random inputs of the checks drawn from it; gradebook.csv's variant "
      "column names it)");
  command_->add_flag("--variant-from-folder", variant_from_folder_,
                     "Each student's sub-folder name is their variant ID, as `exercise init --variant NAME` gave them "
                     "(not with --variant)");
  command_->add_option("--jobs", jobs_, "Submissions graded at once (default: the number of cores)")
      ->check(CLI::Range(1, 1024));
  command_->add_option("--timeout", timeout_seconds_, "Seconds allowed per request (default 10)")
      ->check(CLI::Validator(seconds_problem, "S"));
  command_->add_option("--build-timeout", build_seconds_,
                       "Seconds allowed for a C++ submission's build, configure and compile together (default 300)")
      ->check(CLI::Validator(seconds_problem, "S"));
  // The worker (grading.hpp says why one process per submission): not for users, so not listed.
  command_->add_option("--worker", worker_folder_)->group("");
  command_->add_option("--student", worker_student_)->group("");
}

int ExerciseGradeCommand::run() const { return worker_folder_.empty() ? grade_class() : grade_one(); }

// One submission: graded, its files written into --out, its row as one JSON line on stdout. Whatever
// goes wrong is the row's diagnosis, never a stop.
int ExerciseGradeCommand::grade_one() const {
  const NamedExercise named = exercise_named(name_, model_, "grade");
  const auto& exercise = named.exercise;
  exercises::GradedSubmission graded;
  const exercises::Variant variant =
      variant_option_->count() > 0 ? exercises::Variant(variant_) : exercises::Variant();
  try {
    graded = exercises::grade_submission(exercise, worker_student_, worker_folder_,
                                         (fs::path(out_dir_) / "build").string(), timeout_seconds_, build_seconds_,
                                         variant);
    const auto json = graded.checked ? exercises::results_json(graded.results, "", variant)
                                     : exercises::results_json({}, graded.row.diagnosis, variant);
    write_file_atomically((fs::path(out_dir_) / "results.json").string(), json.dump(2) + "\n");
    write_file_atomically((fs::path(out_dir_) / "report.html").string(),
                          exercises::results_html(exercise, graded.results,
                                                  graded.checked ? graded.command : graded.row.diagnosis, variant));
    if (!graded.build_log.empty())
      write_file_atomically((fs::path(out_dir_) / "build.log").string(), graded.build_log);
    if (const exercises::CheckResult* traced = exercises::failing_trace_check(graded.results))
      write_file_atomically((fs::path(out_dir_) / "trace.html").string(), exercises::trace_page_html(exercise, *traced, variant));
  } catch (const std::exception& error) {
    graded.row.student = worker_student_;
    graded.row.exercise = exercise.name;
    graded.row.variant = variant.id().value_or("");
    graded.row.passed = 0;
    graded.row.diagnosis = fmt::format("not graded: {}", error.what());
  }
  std::cout << exercises::row_to_json_line(graded.row) << std::flush;
  return exit_success;
}

int ExerciseGradeCommand::grade_class() const {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  // 1. Everything checked before any submission is run; nothing in OUT overwritten.
  const NamedExercise named = exercise_named(name_, model_, "grade");
  const auto& exercise = named.exercise;
  if (submissions_.empty()) throw std::invalid_argument("exercise grade: --submissions DIR is required");
  if (variant_from_folder_ && variant_option_->count() > 0) {
    throw std::invalid_argument("exercise grade: --variant ID and --variant-from-folder exclude each other (one "
                                "variant for all, or each student's folder name)");
  }
  if (variant_option_->count() > 0) {
    if (const std::string problem = exercises::variant_id_problem(variant_); !problem.empty())
      throw std::invalid_argument("exercise grade: --variant: " + problem);
  }
  std::error_code error;
  if (!fs::is_directory(submissions_, error))
    throw std::invalid_argument(fmt::format("exercise grade: --submissions '{}' is not a folder", submissions_));
  const std::vector<std::string> students = exercises::list_students(submissions_);
  if (students.empty())
    throw std::invalid_argument(fmt::format("exercise grade: '{}' holds no sub-folder (one per student)", submissions_));
  const fs::path out(out_dir_);
  const fs::path gradebook = out / "gradebook.csv";
  if (fs::exists(gradebook, error))
    throw std::invalid_argument(fmt::format("exercise grade: '{}' exists already (nothing was written)", gradebook.string()));
  for (const std::string& student : students) {
    if (fs::exists(out / student, error))
      throw std::invalid_argument(
          fmt::format("exercise grade: '{}' exists already (nothing was written)", (out / student).string()));
  }
  if (variant_from_folder_) {
    for (const std::string& student : students) {
      if (!exercises::variant_id_problem(student).empty())
        throw std::invalid_argument(fmt::format("exercise grade: --variant-from-folder: the folder name '{}' holds "
                                                "control characters; it cannot be a variant ID",
                                                printable(student)));
    }
  }
  if (fs::equivalent(out, submissions_, error))
    throw std::invalid_argument("exercise grade: --out must not be the --submissions folder");
  ensure_directory(out_dir_);
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) throw std::runtime_error("exercise grade: cannot find numlab itself (/proc/self/exe): " + error.message());

  // 2. One worker process per submission, --jobs at a time.
  std::vector<std::vector<std::string>> workers;
  for (const std::string& student : students) {
    workers.push_back({self.string(), "exercise", "grade", exercise.name, "--worker",
                       (fs::absolute(submissions_) / student).string(), "--student", student, "--out",
                       (fs::absolute(out) / student).string(), "--timeout", fmt::format("{}", timeout_seconds_),
                       "--build-timeout", fmt::format("{}", build_seconds_)});
    if (variant_from_folder_ || variant_option_->count() > 0) {
      // One word, so that an ID that starts with '-' is not read as an option.
      workers.back().push_back("--variant=" + (variant_from_folder_ ? student : variant_));
    }
    if (!named.model_file.empty()) {
      workers.back().push_back("--model");
      workers.back().push_back(fs::absolute(named.model_file).string());
    }
  }
  const int jobs = jobs_ > 0 ? jobs_ : default_jobs();
  const auto outputs = exercises::run_workers(workers, jobs);

  // 3. The gradebook, in name order.
  std::vector<exercises::GradeRow> rows;
  const int total = static_cast<int>(exercise.battery(exercises::Variant()).size());
  int all_pass = 0;
  for (std::size_t k = 0; k < students.size(); ++k) {
    exercises::GradeRow row;
    try {
      row = exercises::row_from_json_line(outputs[k].stdout_text);
    } catch (const std::exception& failure) {
      row.student = students[k];
      row.exercise = exercise.name;
      row.variant = variant_from_folder_ ? students[k] : variant_option_->count() > 0 ? variant_ : "";
      row.total = total;
      row.seconds = outputs[k].seconds;
      row.diagnosis = fmt::format("not graded: the grading process {} ({})",
                                  outputs[k].status < 0 ? "could not start"
                                                        : exercises::describe_wait_status(outputs[k].status),
                                  failure.what());
    }
    if (row.total > 0 && row.passed == row.total) ++all_pass;
    rows.push_back(std::move(row));
  }
  write_file_atomically(gradebook.string(), exercises::gradebook_csv(rows));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::cout << fmt::format("Graded {} submissions of '{}' in {:.1f} s ({:.3f} s each, {} at once): {} pass every "
                           "check, {} do not.\nWrote {} and a report.html, results.json per student.\n",
                           rows.size(), exercise.name, seconds, seconds / static_cast<double>(rows.size()), jobs,
                           all_pass, static_cast<int>(rows.size()) - all_pass, gradebook.string());
  return all_pass == static_cast<int>(rows.size()) ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
