#include "exercises/grading.hpp"
#include "exercises/command_line.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <numlab/printable_text.hpp>
#include <stdexcept>
#include <thread>

#include "exercises/child_process.hpp"
#include "exercises/child_session.hpp"
#include "exercises/descendants.hpp"

extern char** environ;

namespace numlab::exercises {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool is_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

// The first line of `text` that names an error (a compiler's "error:", CMake's "CMake Error"), else
// its first line that is not blank; shortened to 300 bytes.
std::string telling_line(const std::string& text) {
  std::string first;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.find("error") != std::string::npos || line.find("Error") != std::string::npos) {
      first = line;
      break;
    }
  }
  if (first.size() > 300) first = first.substr(0, 300) + "...";
  return first;
}

// One step of a C++ build, run as a sandboxed child (own process group; it and every process it
// leaves ended by stop()) until `deadline`. "" when it succeeded, else why not.
std::string run_build_step(const std::string& step, const std::string& program,
                           const std::vector<std::string>& arguments, const std::string& directory,
                           Clock::time_point deadline, double build_seconds, std::string& log) {
  CappedText errors(ChildSession::output_cap);
  try {
    ChildProcess process(program, arguments, directory);
    const bool exited = process.wait_for_exit(deadline, errors);
    const int status = process.stop(Clock::duration::zero(), errors);
    const std::string text = errors.take();
    log += "$ " + shell_words([&] {
      std::vector<std::string> words{"cmake"};
      words.insert(words.end(), arguments.begin(), arguments.end());
      return words;
    }()) + "\n" + text + (text.empty() || text.back() == '\n' ? "" : "\n");
    if (!exited) return fmt::format("does not build: {} took more than {:g} s (stopped)", step, build_seconds);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    const std::string line = telling_line(text);
    return fmt::format("does not build: {} {}{}{}", step, describe_wait_status(status), line.empty() ? "" : ": ",
                       printable(line));
  } catch (const std::exception& error) {
    return fmt::format("does not build: cmake could not be started: {}", error.what());
  }
}

// The installation numlab runs from (PREFIX of PREFIX/bin/numlab), for find_package(numlab).
std::string numlab_prefix() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return "";
  return self.parent_path().parent_path().string();
}

// Builds a C++ submission into `build_folder`; "" when build/solution is there, else why not.
std::string build_cpp(const fs::path& folder, const fs::path& build_folder, double build_seconds, std::string& log) {
  const std::string cmake = find_on_path("cmake");
  if (cmake.empty()) return "does not build: cmake is not on PATH";
  std::error_code error;
  fs::create_directories(build_folder, error);
  if (error) return fmt::format("does not build: cannot make {}: {}", build_folder.string(), error.message());
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(build_seconds));
  std::vector<std::string> configure{"-S", fs::absolute(folder).string(), "-B", fs::absolute(build_folder).string(),
                                     "-DCMAKE_BUILD_TYPE=Release"};
  // find_package(numlab) as the starter's check command finds it: the installation numlab runs
  // from, after the folders CMAKE_PREFIX_PATH names in the environment (an instructor's own).
  std::string prefixes = numlab_prefix();
  if (const char* given = std::getenv("CMAKE_PREFIX_PATH"); given != nullptr && *given != '\0') {
    std::string listed = given;
    std::replace(listed.begin(), listed.end(), ':', ';');
    prefixes = listed + (prefixes.empty() ? "" : ";" + prefixes);
  }
  if (!prefixes.empty()) configure.push_back("-DCMAKE_PREFIX_PATH=" + prefixes);
  std::string why = run_build_step("cmake (configure)", cmake, configure, build_folder.string(), deadline, build_seconds, log);
  if (!why.empty()) return why;
  why = run_build_step("cmake --build", cmake, {"--build", fs::absolute(build_folder).string()}, build_folder.string(), deadline,
                       build_seconds, log);
  if (!why.empty()) return why;
  if (!is_file(build_folder / "solution")) return "does not build: the build made no build/solution";
  return "";
}

}  // namespace

std::optional<Language> detect_language(const std::string& folder) {
  const fs::path root(folder);
  if (is_file(root / "solution.py")) return Language::python;
  if (is_file(root / "solution.cpp") && is_file(root / "CMakeLists.txt")) return Language::cpp;
  if (is_file(root / "solution.m")) return Language::octave;
  return std::nullopt;
}

GradedSubmission grade_submission(const Exercise& exercise, const std::string& student, const std::string& folder,
                                  const std::string& build_folder, double timeout_seconds, double build_seconds,
                                  const Variant& variant) {
  const Clock::time_point start = Clock::now();
  GradedSubmission graded;
  graded.row.student = student;
  graded.row.exercise = exercise.name;
  graded.row.variant = variant.id().value_or("");
  graded.row.total = static_cast<int>(exercise.battery(variant).size());
  // Processes the program or the build leave come here (as for `exercise check`), and a write to
  // a program that died is EPIPE, not the end of the worker.
  std::signal(SIGPIPE, SIG_IGN);
  prctl(PR_SET_CHILD_SUBREAPER, 1);

  const fs::path root = fs::absolute(folder);
  const std::optional<Language> language = detect_language(root.string());
  std::vector<std::string> command;
  if (!language) {
    graded.row.diagnosis = "no starter file: solution.py, solution.cpp with CMakeLists.txt, or solution.m";
  } else if (*language == Language::python) {
    command = {"python3", (root / "solution.py").string()};
  } else if (*language == Language::octave) {
    command = {"octave-cli", "--no-gui", "--quiet", (root / "solution.m").string()};
  } else {
    const std::string why = build_cpp(root, build_folder, build_seconds, graded.build_log);
    if (why.empty()) {
      command = {(fs::absolute(build_folder) / "solution").string()};
    } else {
      graded.row.diagnosis = why;
    }
  }
  graded.command = shell_words(command);
  if (!command.empty()) {
    try {
      ChildSession session(exercise.name, command, timeout_seconds);
      graded.results = run_checks(exercise, session, variant);
      session.finish();
      graded.checked = true;
    } catch (const std::exception& error) {
      graded.row.diagnosis = fmt::format("cannot start: {}", error.what());
    }
  }
  if (graded.checked) {
    graded.row.total = static_cast<int>(graded.results.size());
    graded.row.passed = static_cast<int>(std::count_if(graded.results.begin(), graded.results.end(),
                                                       [](const CheckResult& r) { return r.status == CheckStatus::pass; }));
    if (const std::optional<Diagnosis> diagnosis = overall_diagnosis(graded.results)) {
      graded.row.diagnosis = diagnosis->evidence;
    } else {
      for (const CheckResult& result : graded.results) {
        if (result.status == CheckStatus::pass) continue;
        graded.row.diagnosis = !result.hint.empty() ? result.hint : result.message;
        break;
      }
    }
  }
  graded.row.seconds = seconds_since(start);
  return graded;
}

std::string row_to_json_line(const GradeRow& row) {
  const nlohmann::ordered_json json = {{"student", row.student},   {"exercise", row.exercise},
                                       {"variant", row.variant},   {"passed", row.passed},
                                       {"total", row.total},       {"diagnosis", row.diagnosis},
                                       {"seconds", row.seconds}};
  return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

GradeRow row_from_json_line(const std::string& line) {
  const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
  if (!json.is_object()) throw std::invalid_argument("the worker's reply is not a JSON object");
  try {
    GradeRow row;
    row.student = json.at("student").get<std::string>();
    row.exercise = json.at("exercise").get<std::string>();
    row.variant = json.at("variant").get<std::string>();
    row.passed = json.at("passed").get<int>();
    row.total = json.at("total").get<int>();
    row.diagnosis = json.at("diagnosis").get<std::string>();
    row.seconds = json.at("seconds").get<double>();
    return row;
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(fmt::format("the worker's reply lacks a field: {}", error.what()));
  }
}

std::vector<std::string> list_students(const std::string& submissions) {
  std::vector<std::string> students;
  for (const fs::directory_entry& entry : fs::directory_iterator(submissions)) {
    const std::string name = entry.path().filename().string();
    std::error_code error;
    if (name.empty() || name.front() == '.' || !entry.is_directory(error)) continue;
    students.push_back(name);
  }
  std::sort(students.begin(), students.end());
  return students;
}

namespace {

// One worker: spawned (posix_spawn: no fork of this multi-threaded process, nothing run between
// the clone and the exec), its stdout read to the end, then it alone is waited for.
WorkerOutput run_worker(const std::vector<std::string>& arguments) {
  WorkerOutput output;
  const Clock::time_point start = Clock::now();
  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0) {
    output.status = -1;
    output.stdout_text = fmt::format("cannot make a pipe: {}", std::strerror(errno));
    return output;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 1);  // dup2 clears close-on-exec on 1
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> words = arguments;
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[1]);
  if (failed != 0) {
    close(ends[0]);
    output.status = -1;
    output.stdout_text = fmt::format("cannot start the worker: {}", std::strerror(failed));
    return output;
  }
  char buffer[65536];
  for (;;) {
    const ssize_t got = read(ends[0], buffer, sizeof buffer);
    if (got > 0) {
      output.stdout_text.append(buffer, static_cast<std::size_t>(got));
      continue;
    }
    if (got < 0 && errno == EINTR) continue;
    break;
  }
  close(ends[0]);
  while (waitpid(pid, &output.status, 0) < 0 && errno == EINTR) {
  }
  output.seconds = seconds_since(start);
  return output;
}

}  // namespace

std::vector<WorkerOutput> run_workers(const std::vector<std::vector<std::string>>& arguments, int jobs) {
  std::vector<WorkerOutput> outputs(arguments.size());
  // Workers' processes whose worker died come here, not to init: ended below, once all are done.
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t k = next++; k < arguments.size(); k = next++) outputs[k] = run_worker(arguments[k]);
  };
  const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), arguments.size());
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  end_adopted_children(false);  // one thread again: nothing of ours is running any more
  return outputs;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string gradebook_csv(const std::vector<GradeRow>& rows) {
  std::string csv = "student,exercise,variant,passed,total,diagnosis,seconds\n";
  for (const GradeRow& row : rows) {
    std::string diagnosis = row.diagnosis;  // one line per row: a message's line breaks become spaces
    std::replace(diagnosis.begin(), diagnosis.end(), '\n', ' ');
    std::replace(diagnosis.begin(), diagnosis.end(), '\r', ' ');
    csv += fmt::format("{},{},{},{},{},{},{:.3f}\n", csv_field(row.student), csv_field(row.exercise),
                       csv_field(row.variant), row.passed, row.total, csv_field(printable(diagnosis)),
                       row.seconds);
  }
  return csv;
}

}  // namespace numlab::exercises
