#pragma once
// The real Session of `numlab exercise check`: the student's program runs as a sandboxed child
// (child_process.hpp) and is spoken to in JSON Lines (docs/exercises.md, "The protocol").
//
// The student's program cannot hurt the checker: each request has a time limit, after which the
// program's whole process group is killed; a crash, an early exit, a line that is not a JSON
// object, a wrong id or a reply over 16 MiB is a ChildFailure with a clear message; a program that
// died in one check is started again at the next. It runs in a fresh temporary directory (removed
// afterwards) with only the arguments the student gave, and no process of it outlives the session.
// Python and Octave programs are watched for calls to the library functions the exercise forbids
// (call_watch.hpp): the watch lives in the folder's .numlab-watch/.

#include <sys/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "exercises/child_process.hpp"
#include "exercises/session.hpp"

namespace numlab::exercises {

class ChildSession : public Session {
 public:
  // Each stderr kept per check, and the longest reply line read.
  static constexpr std::size_t output_cap = 64 * 1024;
  static constexpr std::size_t reply_cap = 16 * 1024 * 1024;

  // Starts `command` (command[0] found on PATH unless it holds a '/'; later arguments that name
  // existing files or folders passed as absolute paths). Throws std::invalid_argument
  // "exercise check: cannot run 'X': <reason>" when it cannot be started.
  ChildSession(std::string exercise, std::vector<std::string> command, double timeout_seconds);
  ~ChildSession() override;
  ChildSession(const ChildSession&) = delete;
  ChildSession& operator=(const ChildSession&) = delete;

  nlohmann::json ask(nlohmann::json request) override;
  double seconds_per_request() const override;
  void begin_check() override;
  std::string take_output() override;
  LibraryCalls take_library_calls() override;

  // Closes the program's stdin, gives it 1 s to exit, then kills its process group.
  void finish();

  // For tests: the running program's process group (its pid), 0 when none runs; its directory.
  pid_t process_group() const;
  const std::string& working_directory() const { return directory_; }
  const std::vector<std::string>& resolved_command() const { return command_; }

 private:
  void start();
  void stop_now();
  [[noreturn]] void fail(const std::string& message);  // stops the program, throws ChildFailure
  std::string ended_message(long long id);
  void collect_calls();  // the watch's log read into calls_ (before the folder goes)

  std::string exercise_;
  std::vector<std::string> command_;  // resolved: absolute program, absolute file arguments
  double timeout_seconds_;
  std::string directory_;
  std::unique_ptr<ChildProcess> process_;
  std::string start_error_;  // why a restart failed; the next request reports it
  CappedText output_{output_cap};
  std::vector<double> seconds_;
  bool replied_since_start_ = false;  // the first reply after a start waited for the start-up: not timed
  long long last_id_ = 0;
  std::uintmax_t call_log_offset_ = 0;  // what of the watch's log was read
  LibraryCalls calls_;                  // noticed and not yet taken
};

}  // namespace numlab::exercises
