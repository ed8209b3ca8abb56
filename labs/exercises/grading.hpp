#pragma once
// `numlab exercise grade` (docs/exercises.md, "Grading a class"): every sub-folder of a folder is one
// student's submission, laid out as `exercise init` writes it; each is checked exactly as
// `exercise check` checks it, and the class gets one gradebook row per student.
//
// Why one process per submission. ChildProcess and ChildSession are made for one program at a time
// in one thread: ChildProcess::stop() ends every child of numlab that is not a registered running
// leader (descendants.hpp), and a program another thread has just forked is such a child until
// its exec succeeded and it was registered; ChildSession keeps the running group, its folder and
// the signal handlers' previous actions in globals without a lock; the leaders' table holds 64.
// So each submission is graded by a worker, `numlab exercise grade NAME --worker FOLDER` started
// from /proc/self/exe with posix_spawn (no ChildProcess in the threads), single-threaded and its
// own child subreaper: what ends "every child" there ends only that student's processes.

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"
#include "exercises/starters.hpp"

namespace numlab::exercises {

struct GradeRow {
  std::string student;
  std::string exercise;
  std::string variant;  // the variant's ID (--variant, or the folder's name with --variant-from-folder); "" for none
  int passed = 0;
  int total = 0;
  std::string diagnosis;  // the run's diagnosis, else the first failing check's hint or message; or why nothing ran
  double seconds = 0.0;   // the submission's whole grading (build included)
};

// The starter file present in `folder`: solution.py, else solution.cpp with CMakeLists.txt, else
// solution.m; nothing when none is.
std::optional<Language> detect_language(const std::string& folder);

// One submission graded in this process (the worker's job): built first when it is C++ (cmake
// into `build_folder`, within `build_seconds`, every process of the build ended), then checked
// through a ChildSession. `results` and `command` are what report.html and results.json are made
// from; when nothing could be run, `results` is empty and `row.diagnosis` says why.
struct GradedSubmission {
  GradeRow row;
  std::vector<CheckResult> results;
  std::string command;    // the program checked, as shell words
  bool checked = false;   // the checks ran
  std::string build_log;  // C++: the build's commands and their stderr (64 KiB each at most)
};
// The battery is the one of `variant` (variant.hpp), and the row names it.
GradedSubmission grade_submission(const Exercise& exercise, const std::string& student, const std::string& folder,
                                  const std::string& build_folder, double timeout_seconds, double build_seconds,
                                  const Variant& variant = Variant());

// The worker's one line on stdout, and back.
std::string row_to_json_line(const GradeRow& row);
GradeRow row_from_json_line(const std::string& line);  // throws std::invalid_argument

// The sub-folders of `submissions` (names not starting with '.'), sorted by name.
std::vector<std::string> list_students(const std::string& submissions);

// Runs each of `arguments` (argv[0] an absolute path) as a process, on `jobs` threads, each started
// with posix_spawn (stdin /dev/null, stdout read whole), and returns each one's stdout, wait
// status (-1 when it could not start) and wall time, in the order given. Processes this process
// adopts meanwhile (it is made a child subreaper) are ended once all have finished.
struct WorkerOutput {
  std::string stdout_text;
  int status = 0;
  double seconds = 0.0;
};
std::vector<WorkerOutput> run_workers(const std::vector<std::vector<std::string>>& arguments, int jobs);

// gradebook.csv: the header and one row per student, fields quoted where CSV needs it.
std::string gradebook_csv(const std::vector<GradeRow>& rows);

// A CSV field: as it is, or quoted ("" for ") when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

}  // namespace numlab::exercises
