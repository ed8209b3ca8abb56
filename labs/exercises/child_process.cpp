#include "exercises/child_process.hpp"

#include "exercises/descendants.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fmt/format.h>
#include <numlab/printable_text.hpp>
#include <system_error>
#include <utility>

namespace numlab::exercises {

// ---------------------------------------------------------------------------------------------
// The kept stderr.

void CappedText::append(std::string_view bytes) {
  const std::size_t room = cap_ - std::min(cap_, kept_.size());
  const std::size_t taken = std::min(room, bytes.size());
  kept_.append(bytes.substr(0, taken));
  dropped_ += bytes.size() - taken;
}

std::string CappedText::take() {
  std::string text;
  std::size_t start = 0;
  while (start < kept_.size()) {
    const std::size_t end = kept_.find('\n', start);
    if (end == std::string::npos) {
      text += printable(std::string_view(kept_).substr(start));
      break;
    }
    text += printable(std::string_view(kept_).substr(start, end - start));
    text += '\n';
    start = end + 1;
  }
  if (dropped_ > 0) {
    if (!text.empty() && text.back() != '\n') text += '\n';
    text += fmt::format("[... {} bytes more]", dropped_);
  }
  clear();
  return text;
}

void CappedText::clear() {
  kept_.clear();
  dropped_ = 0;
}

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return fmt::format("exited with code {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    return name ? fmt::format("was killed by signal SIG{}", name) : fmt::format("was killed by signal {}", signal);
  }
  return fmt::format("ended with wait status {}", status);
}

// ---------------------------------------------------------------------------------------------
// Starting the child.

namespace {

[[noreturn]] void throw_errno(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

// A pipe whose ends close themselves unless released; both ends close-on-exec and above 0..2, so
// that dup2 onto the child's stdin/stdout/stderr always makes a fresh, inherited descriptor.
struct Pipe {
  std::array<int, 2> ends{-1, -1};
  Pipe() {
    if (pipe2(ends.data(), O_CLOEXEC) != 0) throw_errno("pipe");
    for (int& end : ends) {
      if (end > 2) continue;
      const int moved = fcntl(end, F_DUPFD_CLOEXEC, 3);
      if (moved < 0) throw_errno("fcntl");
      close(end);
      end = moved;
    }
  }
  ~Pipe() {
    for (int end : ends)
      if (end >= 0) close(end);
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  int release(int which) { return std::exchange(ends[which], -1); }
  int read_end() const { return ends[0]; }
  int write_end() const { return ends[1]; }
};

// What the child reports through the close-on-exec status pipe when it cannot exec.
struct StartFailure {
  int stage;  // 1: chdir, 2: exec
  int error;
};

// After fork: only async-signal-safe calls from here on.
[[noreturn]] void become_the_program(const char* program, char* const argv[], char* const envp[], const char* directory,
                                     pid_t parent, int stdin_read, int stdout_write, int stderr_write, int status_write) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);  // numlab died before the death signal was armed
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  // numlab ignores SIGPIPE and catches SIGINT/SIGTERM; the program starts with the defaults.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (int signal = 1; signal < NSIG; ++signal) sigaction(signal, &default_action, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);

  dup2(stdin_read, 0);
  dup2(stdout_write, 1);
  dup2(stderr_write, 2);
  // Nothing else of numlab's crosses exec (the status pipe is close-on-exec already).
  if (close_range(3, ~0U, CLOSE_RANGE_CLOEXEC) != 0) {
    const long limit = std::min(sysconf(_SC_OPEN_MAX), 65536L);
    for (int fd = 3; fd < limit; ++fd)
      if (fd != status_write) close(fd);
  }
  StartFailure failure{1, 0};
  if (chdir(directory) == 0) {
    execve(program, argv, envp);
    failure.stage = 2;
  }
  failure.error = errno;
  [[maybe_unused]] const ssize_t ignored = write(status_write, &failure, sizeof failure);
  _exit(127);
}

std::string start_failure_reason(const StartFailure& failure) {
  const std::string reason = std::strerror(failure.error);
  if (failure.stage == 1) return fmt::format("cannot enter its working directory ({})", reason);
  if (failure.error == ENOENT) return fmt::format("its #! interpreter or loader was not found ({})", reason);
  return fmt::format("the system refused to start it ({})", reason);
}

// numlab's environment with each "NAME=VALUE" of `settings` put in place of NAME's (or added).
std::vector<std::string> environment_with(const std::vector<std::string>& settings) {
  std::vector<std::string> result;
  const auto name_of = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string inherited = *entry;
    const bool replaced = std::any_of(settings.begin(), settings.end(),
                                      [&](const std::string& setting) { return name_of(setting) == name_of(inherited); });
    if (!replaced) result.push_back(inherited);
  }
  result.insert(result.end(), settings.begin(), settings.end());
  return result;
}

void set_nonblocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

}  // namespace

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& arguments,
                           const std::string& directory, const std::vector<std::string>& environment) {
  Pipe in, out, err, status;
  std::vector<std::string> words{program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::vector<std::string> settings = environment_with(environment);
  std::vector<char*> envp;
  for (std::string& setting : settings) envp.push_back(setting.data());
  envp.push_back(nullptr);

  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) throw_errno("fork");
  if (pid_ == 0)
    become_the_program(program.c_str(), argv.data(), envp.data(), directory.c_str(), parent, in.read_end(),
                       out.write_end(), err.write_end(), status.write_end());
  setpgid(pid_, pid_);  // also done by the child; whichever comes first

  close(status.release(1));
  StartFailure failure{};
  ssize_t got = 0;
  do {
    got = read(status.read_end(), &failure, sizeof failure);
  } while (got < 0 && errno == EINTR);
  if (got == static_cast<ssize_t>(sizeof failure)) {
    int child_status = 0;
    while (waitpid(pid_, &child_status, 0) < 0 && errno == EINTR) {
    }
    status_ = child_status;
    throw StartError(start_failure_reason(failure));
  }
  register_running_program(pid_);
  stdin_ = in.release(1);
  stdout_ = out.release(0);
  stderr_ = err.release(0);
  for (int fd : {stdin_, stdout_, stderr_}) set_nonblocking(fd);
}

ChildProcess::~ChildProcess() {
  CappedText ignored(0);
  stop(Clock::duration::zero(), ignored);
}

// ---------------------------------------------------------------------------------------------
// Talking to it.

namespace {

// While nothing arrives, whether the program is still alive is looked at this often.
constexpr int exit_check_ms = 50;

int milliseconds_until(ChildProcess::Clock::time_point deadline) {
  const auto left = deadline - ChildProcess::Clock::now();
  if (left <= ChildProcess::Clock::duration::zero()) return 0;
  const auto ms = std::chrono::ceil<std::chrono::milliseconds>(left).count();
  return static_cast<int>(std::min<long long>(ms, 1'000'000));
}

enum class ReadResult { data, nothing_now, finished };

// Reads what `fd` holds now (it is non-blocking) into `sink`; `finished` at end of file or on an
// error (the fd is done).
template <class Sink>
ReadResult read_available(int fd, Sink&& sink) {
  std::array<char, 65536> buffer;
  const ssize_t got = read(fd, buffer.data(), buffer.size());
  if (got > 0) {
    sink(std::string_view(buffer.data(), static_cast<std::size_t>(got)));
    return ReadResult::data;
  }
  return got < 0 && (errno == EAGAIN || errno == EINTR) ? ReadResult::nothing_now : ReadResult::finished;
}

}  // namespace

void ChildProcess::close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

ChildProcess::Outcome ChildProcess::exchange(std::string_view request, Clock::time_point deadline,
                                             std::size_t max_line, std::string& line, CappedText& errors) {
  const auto keep_errors = [&](std::string_view bytes) { errors.append(bytes); };
  const auto keep_pending = [&](std::string_view bytes) { pending_.append(bytes); };
  std::size_t written = 0;
  bool writing = stdin_ >= 0;
  for (;;) {
    if (const std::size_t end = pending_.find('\n'); end != std::string::npos) {
      if (end > max_line) return Outcome::line_too_long;
      // What the program wrote to stderr before replying belongs to this request.
      for (int round = 0; round < 64 && stderr_ >= 0; ++round) {
        const ReadResult result = read_available(stderr_, keep_errors);
        if (result == ReadResult::finished) close_fd(stderr_);
        if (result != ReadResult::data) break;
      }
      line.assign(pending_, 0, end);
      pending_.erase(0, end + 1);
      return Outcome::line;
    }
    if (pending_.size() > max_line) return Outcome::line_too_long;
    if (stdout_ < 0) return Outcome::ended;
    const int wait_ms = milliseconds_until(deadline);
    if (wait_ms == 0) return Outcome::timed_out;

    std::array<pollfd, 3> fds{pollfd{stdout_, POLLIN, 0}, pollfd{stderr_, POLLIN, 0},
                              pollfd{writing ? stdin_ : -1, POLLOUT, 0}};
    const int ready = poll(fds.data(), fds.size(), std::min(wait_ms, exit_check_ms));
    if (ready < 0) {
      if (errno == EINTR) continue;
      throw_errno("poll");
    }
    if (ready == 0 && leader_exited()) return Outcome::ended;
    if (fds[2].revents != 0) {
      const ssize_t put = write(stdin_, request.data() + written, request.size() - written);
      if (put > 0) written += static_cast<std::size_t>(put);
      // EPIPE: the program stopped reading; what it does next shows on its stdout.
      if (written == request.size() || (put < 0 && errno != EAGAIN && errno != EINTR)) writing = false;
    }
    if (fds[1].revents != 0 && read_available(stderr_, keep_errors) == ReadResult::finished)
      close_fd(stderr_);
    if (fds[0].revents != 0 && read_available(stdout_, keep_pending) == ReadResult::finished)
      close_fd(stdout_);
  }
}

void ChildProcess::drain(int timeout_ms, CappedText& errors) {
  const auto keep_errors = [&](std::string_view bytes) { errors.append(bytes); };
  std::array<pollfd, 2> fds{pollfd{stdout_, POLLIN, 0}, pollfd{stderr_, POLLIN, 0}};
  if (poll(fds.data(), fds.size(), timeout_ms) <= 0) return;
  if (fds[1].revents != 0 && read_available(stderr_, keep_errors) == ReadResult::finished)
    close_fd(stderr_);
  // Lines after the awaited one are not replies to anything; they are dropped.
  if (fds[0].revents != 0 && read_available(stdout_, [](std::string_view) {}) == ReadResult::finished)
    close_fd(stdout_);
}

// ---------------------------------------------------------------------------------------------
// Ending it.

bool ChildProcess::leader_exited() const {
  if (status_) return true;
  siginfo_t info{};
  return waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_;
}

bool ChildProcess::wait_for_exit(Clock::time_point deadline, CappedText& errors) {
  for (;;) {
    if (leader_exited()) return true;
    const int wait_ms = milliseconds_until(deadline);
    if (wait_ms == 0) return false;
    drain(std::min(wait_ms, 10), errors);
  }
}

int ChildProcess::stop(Clock::duration grace, CappedText& errors) {
  if (status_) return *status_;
  close_fd(stdin_);  // end of input: a well-behaved program returns now
  if (grace > Clock::duration::zero()) wait_for_exit(Clock::now() + grace, errors);
  // The leader is at least a zombie, so its pid still names this group: nothing else is hit.
  kill(-pid_, SIGKILL);
  int leader_status = 0;
  while (waitpid(pid_, &leader_status, 0) < 0 && errno == EINTR) {
  }
  status_ = leader_status;
  unregister_running_program(pid_);
  // Group members whose parents died came to numlab (a child subreaper, see ChildSession).
  for (;;) {
    if (waitpid(-pid_, nullptr, 0) > 0) continue;
    if (errno == EINTR) continue;
    break;
  }
  // So did those that left the group (setsid) or were double-forked: numlab's other children.
  end_adopted_children(true);
  // What the program wrote before it ended; bounded in case something outside the group holds
  // the pipe open and keeps writing.
  for (int round = 0; round < 64 && (stderr_ >= 0 || stdout_ >= 0); ++round) drain(0, errors);
  close_fd(stdout_);
  close_fd(stderr_);
  pending_.clear();
  return leader_status;
}

}  // namespace numlab::exercises
