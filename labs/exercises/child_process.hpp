#pragma once
// One run of the student's program as a child process (POSIX: fork, exec, pipes, poll, kill).
// It runs in its own process group, in a given working directory, with only stdin/stdout/stderr
// open, no core dumps, and killed if numlab dies. ChildSession (child_session.hpp) speaks the
// protocol over it; this file only moves bytes and ends processes.

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace numlab::exercises {

// The program could not be started at all (exec failed in the child, or chdir did); what() is the
// reason, e.g. "Exec format error".
class StartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Text the child wrote to stderr, kept up to a cap; what is beyond is counted, not kept.
class CappedText {
 public:
  explicit CappedText(std::size_t cap) : cap_(cap) {}
  void append(std::string_view bytes);
  // The kept text, each line made printable, with "[... N bytes more]" when some was dropped; the
  // buffer starts afresh.
  std::string take();
  void clear();

 private:
  std::size_t cap_;
  std::string kept_;
  std::size_t dropped_ = 0;
};

// "exited with code 3", "was killed by signal SIGSEGV" (from a waitpid status).
std::string describe_wait_status(int status);

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts `program` (an absolute path) with argv = {program, arguments...} in `directory`, with
  // numlab's environment and each "NAME=VALUE" of `environment` set over it.
  // Throws StartError when exec (or chdir) fails in the child, std::system_error when a pipe or
  // fork cannot be made.
  ChildProcess(const std::string& program, const std::vector<std::string>& arguments, const std::string& directory,
               const std::vector<std::string>& environment = {});
  ~ChildProcess();  // stop(0)
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t process_group() const { return pid_; }  // the child is its group's leader
  bool running() const { return !status_.has_value(); }

  enum class Outcome { line, timed_out, ended, line_too_long };
  // Writes `request` to the child's stdin and waits, until `deadline`, for one whole line on its
  // stdout (returned in `line` without the newline, at most `max_line` bytes). stderr goes to
  // `errors` meanwhile. `ended`: its stdout closed, or it exited (a background process it left
  // may hold stdout open). A child that stopped reading its stdin is not an error here: the
  // outcome then comes from its stdout.
  Outcome exchange(std::string_view request, Clock::time_point deadline, std::size_t max_line, std::string& line,
                   CappedText& errors);

  // Waits until the child exits by itself or `deadline` passes (stderr drained meanwhile);
  // true when it exited.
  bool wait_for_exit(Clock::time_point deadline, CappedText& errors);

  // Closes the child's stdin, gives it until `grace` to exit, then kills its whole process group
  // and reaps it, the group members that were reparented to numlab, and every other process that
  // came to numlab (one that left the group with setsid or was double-forked: descendants.hpp).
  // Returns the leader's waitpid status. Safe to call again.
  int stop(Clock::duration grace, CappedText& errors);

 private:
  bool leader_exited() const;  // without reaping it
  void drain(int timeout_ms, CappedText& errors);
  void close_fd(int& fd);

  pid_t pid_ = -1;
  int stdin_ = -1;
  int stdout_ = -1;
  int stderr_ = -1;
  std::string pending_;  // stdout bytes after the last line returned
  std::optional<int> status_;
};

}  // namespace numlab::exercises
