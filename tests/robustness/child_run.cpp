#include "child_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace numlab::robustness {

namespace {

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void become_program(char* const argv[], const char* folder, const char* stdout_file,
                                 const char* stderr_file, long memory_limit_mb) {
  setpgid(0, 0);
  const int in = open("/dev/null", O_RDONLY);
  const int out = open(stdout_file, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const int err = open(stderr_file, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (in < 0 || out < 0 || err < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) _exit(126);
  if (chdir(folder) != 0) _exit(126);
  if (memory_limit_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(memory_limit_mb) * 1024 * 1024;
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  execv(argv[0], argv);
  _exit(127);
}

}  // namespace

ChildResult run_child(const std::string& program, const std::vector<std::string>& arguments, const std::string& folder,
                      const std::string& stdout_file, const std::string& stderr_file, double time_limit,
                      long memory_limit_mb) {
  // 1. The argument vector, built before fork.
  std::vector<std::string> words{program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  // 2. Start the child in its own process group.
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) become_program(argv.data(), folder.c_str(), stdout_file.c_str(), stderr_file.c_str(), memory_limit_mb);
  setpgid(pid, pid);

  // 3. Wait for it, up to the time limit; then kill its whole group.
  ChildResult result;
  int status = 0;
  rusage usage{};
  while (true) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == pid) break;
    if (done < 0) throw std::runtime_error("wait4 failed");
    if (result.seconds > time_limit) {
      result.timed_out = true;
      kill(-pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(-pid, SIGKILL);  // 4. Whatever it left running (none expected).

  result.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in kB
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

}  // namespace numlab::robustness
