// Lab `exercises`: `numlab exercise` from an instructor's side. The exercises, a Python starter
// for gepp, the starter checked (every check fails: not implemented), a correct GEPP and one
// without pivoting checked, and their verdicts read. Every sentence is built from the results.

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "methods/data_dir.hpp"
#include "exercises/checker.hpp"
#include "exercises/child_session.hpp"
#include "exercises/results.hpp"
#include "exercises/starters.hpp"
#include "exercises/trace_page.hpp"
#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"

namespace numlab::cli {

namespace {

using exercises::CheckResult;
using exercises::CheckStatus;

constexpr double time_limit_s = 10.0;

bool python_with_numpy() { return std::system("python3 -c 'import numpy' >/dev/null 2>&1") == 0; }

int count_status(const std::vector<CheckResult>& results, CheckStatus status) {
  int n = 0;
  for (const CheckResult& result : results) n += result.status == status ? 1 : 0;
  return n;
}

// Runs the battery against `python3 program` and prints the text a student sees. Also writes
// results.json and report.html into FOLDER/NAME, as `exercise check --out` does.
std::vector<CheckResult> check(LabSession& session, const exercises::Exercise& exercise, const std::string& program,
                               const std::string& name) {
  const std::vector<std::string> command = {"python3", program};
  session.out() << fmt::format("$ numlab exercise check {} --out {}/{} -- python3 {}\n\n", exercise.name,
                               session.folder(), name, program);
  exercises::ChildSession child(exercise.name, command, time_limit_s);
  const std::vector<CheckResult> results = exercises::run_checks(exercise, child);
  session.out() << exercises::results_text(exercise, results) << '\n';
  const std::string out = session.folder() + "/" + name;
  ensure_directory(out);
  write_file_atomically(out + "/results.json", exercises::results_json(results).dump(2) + "\n");
  write_file_atomically(out + "/report.html", exercises::results_html(exercise, results, "python3 " + program));
  if (const CheckResult* traced = exercises::failing_trace_check(results))
    write_file_atomically(out + "/trace.html", exercises::trace_page_html(exercise, *traced));
  return results;
}

// Of the checks timed against a reference, the one whose time per request is the median (the
// first check's time also holds the program's start); nullptr when none was.
const CheckResult* median_timed_check(const std::vector<CheckResult>& results) {
  std::vector<const CheckResult*> timed;
  for (const CheckResult& result : results) {
    if (!result.references.empty() && result.seconds_per_request > 0) timed.push_back(&result);
  }
  if (timed.empty()) return nullptr;
  std::sort(timed.begin(), timed.end(),
            [](const CheckResult* a, const CheckResult* b) { return a->seconds_per_request < b->seconds_per_request; });
  return timed[timed.size() / 2];
}

// The first line of `text` (a message's first line is its verdict).
std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// Step 1: the exercises a student can be given.
void list_the_exercises(LabSession& session) {
  if (!session.begin_step("The exercises",
                          "`numlab exercise list` names the methods a student writes in their own language. The "
                          "checker runs the student's program as a child process, sends it requests as JSON lines and "
                          "compares each reply with an independent reference: GSL, Eigen, numlab's own steppers, a "
                          "closed form or NIST's certified values.")) return;
  Table list({"exercise", "what the student writes"});
  for (const exercises::Exercise& exercise : exercises::all_exercises()) list.add_row({exercise.name, exercise.summary});
  session.show(list, "exercises");
}

// Step 2: the Python starter for gepp written into the lab's folder; returns its solution.py.
std::string write_a_python_starter(LabSession& session, const exercises::Exercise& gepp) {
  const std::string starter = session.folder() + "/gepp-starter";
  const std::vector<exercises::StarterFile> files = exercises::starter_files(gepp, exercises::Language::python);
  exercises::write_starter_files(starter, files);
  std::string written;
  for (const exercises::StarterFile& file : files) {
    written += fmt::format("{}{} ({} bytes)", written.empty() ? "" : ", ", file.path, file.contents.size());
  }
  if (!session.begin_step("A Python starter for gepp",
                          fmt::format("`numlab exercise init gepp {} --lang python` wrote {}. TASK.md is the task "
                                      "(`numlab exercise show gepp`) with the command that checks it. solution.py "
                                      "already reads the requests and prints the replies; the student writes only "
                                      "solve(request), which as generated raises \"not implemented\".",
                                      starter, written))) return {};
  return starter + "/solution.py";
}

// Step 3: the starter checked: every check fails honestly ("not implemented"), none errs.
void check_the_starter(LabSession& session, const exercises::Exercise& gepp, const std::string& program) {
  if (!session.begin_step("The starter, checked", "Before a line of the method is written, the check runs: the "
                                                  "starter must fail honestly, not crash.")) return;
  const auto starter_results = check(session, gepp, program, "check-starter");
  int not_implemented = 0;
  for (const CheckResult& result : starter_results) {
    not_implemented += result.status == CheckStatus::fail && result.message.find("not implemented") != std::string::npos;
  }
  const int total = static_cast<int>(starter_results.size());
  session.say(fmt::format("{} checks fail with the stub's \"not implemented\", and {} give an error. A failing check means "
                          "the program answered and the answer was wrong (here: it said it cannot answer); an "
                          "error would mean it gave no usable reply (a crash, a hang, garbage).",
                          count_of(not_implemented, total),
                          count_of(count_status(starter_results, CheckStatus::error), total)));
}

// Step 4: a correct GEPP checked, and its speed shown beside a reference.
std::vector<CheckResult> check_a_correct_gepp(LabSession& session, const exercises::Exercise& gepp,
                                              const std::string& examples) {
  if (!session.begin_step("A correct GEPP",
                          "gepp_solution.py does Gaussian elimination with partial pivoting by hand on numpy arrays, "
                          "and reports its pivots as a trace, one entry per column.")) return {};
  const auto correct = check(session, gepp, examples + "/gepp_solution.py", "check-correct");
  session.say(fmt::format("{} checks pass.", count_of(count_status(correct, CheckStatus::pass), static_cast<int>(correct.size()))));
  if (const CheckResult* median = median_timed_check(correct)) {
    const exercises::ReferenceTime& reference = median->references.front();
    session.say(fmt::format("Speed is shown, never judged. On the check of median time, \"{}\", the Python "
                            "solution took {:.3g} ms per request, {} {} ({:.3g} ms); the Python time includes "
                            "the JSON exchange with the child.",
                            median->name, median->seconds_per_request * 1e3,
                            speed_ratio_phrase(median->seconds_per_request, reference.seconds_per_request),
                            reference.name, reference.seconds_per_request * 1e3));
  }
  return correct;
}

// Step 5: a GEPP without pivoting checked, each failing check's message and hint read.
std::vector<CheckResult> check_a_gepp_without_pivoting(LabSession& session, const exercises::Exercise& gepp,
                                                       const std::string& examples) {
  if (!session.begin_step("A GEPP without pivoting",
                          "gepp_no_pivoting.py is the same program with one bug, named in its header: it never swaps "
                          "rows, and eliminates each column with its diagonal entry.")) return {};
  const auto buggy = check(session, gepp, examples + "/gepp_no_pivoting.py", "check-no-pivoting");
  const int buggy_total = static_cast<int>(buggy.size());
  session.say(fmt::format("{} checks fail, {} give an error, and {} pass.", count_of(count_status(buggy, CheckStatus::fail), buggy_total),
                          count_of(count_status(buggy, CheckStatus::error), buggy_total),
                          count_of(count_status(buggy, CheckStatus::pass), buggy_total)));
  for (const CheckResult& result : buggy) {
    if (result.status != CheckStatus::fail) continue;
    session.say(fmt::format("\"{}\" fails. The message: {}. {}", result.name, first_line(result.message),
                            result.hint.empty() ? std::string("No hint fits.") : "The hint: " + result.hint + "."));
  }
  return buggy;
}

// Step 6: where the verdicts were written, and what each program passed.
void read_the_verdicts(LabSession& session, const std::vector<CheckResult>& correct, const std::vector<CheckResult>& buggy) {
  const int buggy_total = static_cast<int>(buggy.size());
  if (!session.begin_step("Reading the verdicts",
                          fmt::format("Each check run above also wrote results.json (the Exercism test-runner v3 shape, "
                                      "for graders and CI) and report.html into {}/check-*. The correct solution passes "
                                      "{}; the one without pivoting passes {}.",
                                      session.folder(), count_of(count_status(correct, CheckStatus::pass), static_cast<int>(correct.size())),
                                      count_of(count_status(buggy, CheckStatus::pass), buggy_total)))) return;
}

}  // namespace

int run_exercises_lab(LabSession& session) {
  list_the_exercises(session);
  if (!python_with_numpy()) {
    session.say("This lab runs Python solutions, and `python3 -c 'import numpy'` fails here: python3 with numpy "
                "is needed (Debian: apt-get install python3 python3-numpy). The lab stops.");
    return 1;
  }
  const exercises::Exercise& gepp = exercises::find_exercise("gepp");
  const std::string program = write_a_python_starter(session, gepp);
  check_the_starter(session, gepp, program);
  const std::string examples = examples_dir();
  const auto correct = check_a_correct_gepp(session, gepp, examples);
  const auto buggy = check_a_gepp_without_pivoting(session, gepp, examples);
  read_the_verdicts(session, correct, buggy);
  // The lab's lesson holds only if the checker told the two programs apart.
  const int correct_passes = count_status(correct, CheckStatus::pass);
  return correct_passes == static_cast<int>(correct.size()) && count_status(buggy, CheckStatus::fail) > 0 ? 0 : 1;
}

}  // namespace numlab::cli
