#include "exercises/child_session.hpp"

#include "exercises/call_watch.hpp"
#include "exercises/command_line.hpp"
#include "exercises/forbidden_calls.hpp"
#include "exercises/descendants.hpp"

#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <mutex>
#include <numlab/printable_text.hpp>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

namespace numlab::exercises {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// The command, made to work from another directory.

std::invalid_argument cannot_run(const std::string& name, const std::string& reason) {
  return std::invalid_argument(fmt::format("exercise check: cannot run '{}': {}", printable(name), reason));
}

// Why `path` cannot be executed, or "" when it can.
std::string why_not_runnable(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) return "no such file";
  if (fs::is_directory(status)) return "it is a folder, not a program";
  if (!fs::is_regular_file(status)) return "it is not a regular file";
  if (access(path.c_str(), X_OK) != 0) return fmt::format("it is not executable ({})", std::strerror(errno));
  return "";
}

std::string resolve_program(const std::string& name) {
  if (name.empty()) throw cannot_run(name, "the command is empty");
  if (name.find('/') != std::string::npos) {
    const fs::path path = fs::absolute(name);
    if (const std::string why = why_not_runnable(path); !why.empty()) throw cannot_run(name, why);
    return path.string();
  }
  if (const std::string found = find_on_path(name); !found.empty()) return found;
  throw cannot_run(name, "not found on PATH");
}

std::vector<std::string> resolve_command(std::vector<std::string> command) {
  if (command.empty()) throw std::invalid_argument("exercise check: no command given after --");
  command[0] = resolve_program(command[0]);
  // The program runs in its own directory: files and folders the student named go there absolute.
  for (std::size_t i = 1; i < command.size(); ++i) {
    std::error_code error;
    if (!command[i].empty() && fs::exists(command[i], error)) command[i] = fs::absolute(command[i]).string();
  }
  return command;
}

std::string make_temporary_directory() {
  const char* tmpdir = std::getenv("TMPDIR");
  const fs::path root = fs::absolute(tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp");
  std::string pattern = (root / "numlab-exercise-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::system_error(errno, std::generic_category(),
                            fmt::format("cannot make its working directory in {}", printable(root.string())));
  return pattern;
}

void forget_running_directory();

void remove_directory(std::string& directory) {
  if (directory.empty()) return;
  forget_running_directory();
  std::error_code ignored;
  fs::remove_all(directory, ignored);
  directory.clear();
}

// ---------------------------------------------------------------------------------------------
// numlab interrupted during a check (SIGINT, SIGTERM, SIGHUP, SIGQUIT): end the program's group and
// every process it left, remove its folder, then die as asked.

constexpr int ending_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
volatile std::sig_atomic_t running_group = 0;
volatile std::sig_atomic_t directory_known = 0;
char running_directory[4096] = "";  // read only while directory_known is set
struct sigaction previous_action[NSIG] {};

void remember_running_directory(const std::string& directory) {
  directory_known = 0;
  if (directory.size() >= sizeof running_directory) return;  // then removed only by the destructor
  std::copy(directory.c_str(), directory.c_str() + directory.size() + 1, running_directory);
  directory_known = 1;
}

void forget_running_directory() { directory_known = 0; }

extern "C" void end_program_and_reraise(int signal) {
  const pid_t group = running_group;
  if (group > 0) kill(-group, SIGKILL);
  end_adopted_children(false);
  if (directory_known) remove_tree(running_directory);
  directory_known = 0;
  running_group = 0;
  if (signal == SIGQUIT) {
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT's default dumps core: not into the user's folder
  }
  sigaction(signal, &previous_action[signal], nullptr);
  raise(signal);  // delivered with the previous disposition once this handler returns
}

void ignore_sigpipe_and_adopt_orphans() {
  static std::once_flag once;
  // A write to a program that died is EPIPE, not the end of numlab.
  std::call_once(once, [] { std::signal(SIGPIPE, SIG_IGN); });
  // Processes whose parent dies come to numlab, so stopping a program ends all of them. Set each
  // time: a forked copy of numlab (a test's checker) does not inherit it.
  prctl(PR_SET_CHILD_SUBREAPER, 1);
}

// Checked at every start, since others (a test framework) may have set their own handlers since.
void end_group_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = end_program_and_reraise;
  sigemptyset(&action.sa_mask);
  for (const int signal : ending_signals) sigaddset(&action.sa_mask, signal);  // one cleanup at a time
  for (const int signal : ending_signals) {
    struct sigaction current {};
    sigaction(signal, nullptr, &current);
    if (current.sa_handler == end_program_and_reraise || current.sa_handler == SIG_IGN) continue;  // ignored stays so
    previous_action[signal] = current;
    sigaction(signal, &action, nullptr);
  }
}

// What a line that is not a reply looks like, for the message.
std::string excerpt(std::string_view line) {
  if (line.empty()) return "(an empty line)";
  constexpr std::size_t shown = 80;
  std::string text = printable(line.substr(0, shown));
  if (line.size() > shown) text += "...";
  return text;
}

// Why `reply` (parsed from `line`) is not a reply to request `id`, or "".
std::string why_not_a_reply(const nlohmann::json& reply, const std::string& line, long long id) {
  if (reply.is_discarded()) {
    const bool non_finite = line.find("NaN") != std::string::npos || line.find("Infinity") != std::string::npos;
    const std::size_t first = line.find_first_not_of(" \t");
    const bool not_an_object = first == std::string::npos || line[first] != '{';
    return fmt::format("the reply is not JSON: {}{}", excerpt(line),
                       non_finite      ? " (NaN and Infinity are not JSON numbers)"
                       : not_an_object ? " (stdout is for replies only: print anything else to stderr)"
                                       : "");
  }
  if (!reply.is_object()) return fmt::format("the reply is not a JSON object: {}", excerpt(line));
  if (!reply.contains("id")) return fmt::format("the reply to request {} has no \"id\"", id);
  const nlohmann::json& echoed = reply["id"];
  if (!echoed.is_number() || echoed.get<double>() != static_cast<double>(id))
    return fmt::format("the reply has id {} but request {} was expected", excerpt(echoed.dump()), id);
  return "";
}

// Where the watch on forbidden library calls lives in the program's folder (call_watch.hpp).
std::string watch_folder(const std::string& directory) { return directory + "/.numlab-watch"; }

bool blank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

// Sends `text` and reads the next line that is not blank, without its '\r': a tolerant reader
// skips blank lines between replies.
ChildProcess::Outcome send_and_read(ChildProcess& process, CappedText& errors, const std::string& text,
                                    ChildProcess::Clock::time_point deadline, std::string& line) {
  using Outcome = ChildProcess::Outcome;
  const auto read_line = [&](std::string_view request, ChildProcess::Clock::time_point until) {
    const Outcome outcome = process.exchange(request, until, ChildSession::reply_cap, line, errors);
    if (outcome == Outcome::line && !line.empty() && line.back() == '\r') line.pop_back();
    return outcome;
  };
  // exchange() returns a line it has already read without sending the request: first the blank
  // lines left after the previous reply go (nothing sent, no wait). A line that is not blank is
  // taken for the reply, as it always was (it cannot be one: its request was never sent).
  while (read_line({}, ChildProcess::Clock::now()) == Outcome::line) {
    if (!blank(line)) return Outcome::line;
  }
  // Then the request goes out whole (a request up to the pipe's 64 KiB is written before any line
  // is read) and blank lines are skipped until the reply.
  Outcome outcome = read_line(text, deadline);
  while (outcome == Outcome::line && blank(line)) outcome = read_line({}, deadline);
  return outcome;
}

ChildProcess::Clock::duration as_duration(double seconds) {
  return std::chrono::duration_cast<ChildProcess::Clock::duration>(std::chrono::duration<double>(seconds));
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle), values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower + upper);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

ChildSession::ChildSession(std::string exercise, std::vector<std::string> command, double timeout_seconds)
    : exercise_(std::move(exercise)), command_(resolve_command(std::move(command))), timeout_seconds_(timeout_seconds) {
  if (!(timeout_seconds > 0.0) || !std::isfinite(timeout_seconds))
    throw std::invalid_argument(
        fmt::format("exercise check: the time limit must be a positive number of seconds, got {}", timeout_seconds));
  ignore_sigpipe_and_adopt_orphans();
  try {
    start();
  } catch (const std::exception& error) {  // StartError, or no directory, pipe or process to be had
    remove_directory(directory_);
    throw cannot_run(command_[0], error.what());
  }
}

ChildSession::~ChildSession() {
  finish();
  remove_directory(directory_);
}

void ChildSession::start() {
  running_group = 0;
  collect_calls();
  remove_directory(directory_);
  directory_ = make_temporary_directory();
  process_.reset();
  end_group_on_interrupt();
  remember_running_directory(directory_);
  const std::vector<std::string> watch = install_call_watch(watch_folder(directory_), forbidden_calls(exercise_));
  call_log_offset_ = 0;
  process_ = std::make_unique<ChildProcess>(command_[0], std::vector<std::string>(command_.begin() + 1, command_.end()),
                                            directory_, watch);
  running_group = process_->process_group();
  replied_since_start_ = false;
}

void ChildSession::stop_now() {
  if (process_ && process_->running()) process_->stop(ChildProcess::Clock::duration::zero(), output_);
  running_group = 0;
}

void ChildSession::finish() {
  if (process_ && process_->running()) process_->stop(std::chrono::seconds(1), output_);
  running_group = 0;
}

void ChildSession::fail(const std::string& message) {
  stop_now();
  throw ChildFailure(message);
}

pid_t ChildSession::process_group() const { return process_ && process_->running() ? process_->process_group() : 0; }

void ChildSession::begin_check() {
  seconds_.clear();
  output_.clear();
  if (process_ && process_->running()) return;
  try {
    start();
  } catch (const std::exception&) {
    // ask() tries again and reports why the program could not be started.
  }
}

std::string ChildSession::take_output() { return output_.take(); }

void ChildSession::collect_calls() {
  if (!directory_.empty()) calls_.add(read_call_log(call_log_path(watch_folder(directory_)), call_log_offset_));
}

LibraryCalls ChildSession::take_library_calls() {
  collect_calls();
  return std::exchange(calls_, LibraryCalls{});
}

double ChildSession::seconds_per_request() const { return median(seconds_); }

std::string ChildSession::ended_message(long long id) {
  const auto deadline = ChildProcess::Clock::now() + as_duration(timeout_seconds_);
  if (!process_->wait_for_exit(deadline, output_))
    return fmt::format("the program closed its output before replying to request {} (the program was stopped)", id);
  const int status = process_->stop(ChildProcess::Clock::duration::zero(), output_);
  return fmt::format("the program {} before replying to request {}", describe_wait_status(status), id);
}

nlohmann::json ChildSession::ask(nlohmann::json request) {
  using Clock = ChildProcess::Clock;
  if (!process_ || !process_->running()) {
    try {
      start();
    } catch (const std::exception& error) {
      throw ChildFailure(fmt::format("the program could not be started again: {}", error.what()));
    }
  }
  const long long id = ++last_id_;
  request["exercise"] = exercise_;
  request["id"] = id;
  const std::string text = request.dump() + '\n';

  const Clock::time_point sent = Clock::now();
  const Clock::time_point deadline = sent + as_duration(timeout_seconds_);
  std::string line;
  switch (send_and_read(*process_, output_, text, deadline, line)) {
    case ChildProcess::Outcome::line: break;
    case ChildProcess::Outcome::timed_out:
      fail(fmt::format("no reply within {:g} s to request {} (the program was stopped)", timeout_seconds_, id));
    case ChildProcess::Outcome::line_too_long:
      fail(fmt::format("the reply to request {} is longer than 16 MiB (the program was stopped)", id));
    case ChildProcess::Outcome::ended: fail(ended_message(id));
  }
  const bool first_reply = !replied_since_start_;
  replied_since_start_ = true;
  if (!first_reply) seconds_.push_back(std::chrono::duration<double>(Clock::now() - sent).count());

  const nlohmann::json reply = nlohmann::json::parse(line, nullptr, false);
  if (const std::string problem = why_not_a_reply(reply, line, id); !problem.empty()) fail(problem);
  if (reply.contains("error")) {
    const nlohmann::json& error = reply["error"];
    const std::string text = error.is_string() ? error.get<std::string>() : error.dump();
    throw StudentError(printable(text.substr(0, 2000)));
  }
  // The first reply's time includes the program's start-up (an import, Octave's start): the same
  // request is sent again, with the same id, and timed instead; its reply and its stderr (the
  // first one's again) are set aside. Whatever goes wrong with it is not this request's failure:
  // an exit shows at the next request, as it would have without the repeat; after a timeout (a
  // late reply would be taken for the next request's) the next request starts the program afresh.
  if (first_reply) {
    CappedText set_aside(0);
    const Clock::time_point again = Clock::now();
    switch (send_and_read(*process_, set_aside, text, again + as_duration(timeout_seconds_), line)) {
      case ChildProcess::Outcome::line:
        seconds_.push_back(std::chrono::duration<double>(Clock::now() - again).count());
        break;
      case ChildProcess::Outcome::ended: break;
      case ChildProcess::Outcome::timed_out:
      case ChildProcess::Outcome::line_too_long: stop_now(); break;
    }
  }
  return reply;
}

}  // namespace numlab::exercises
