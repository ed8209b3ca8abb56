#pragma once
// The hostile children of the sandbox tests (children/*.py) and how to tell that none is left.

#include <signal.h>
#include <sys/types.h>

#include <cerrno>
#include <chrono>
#include <string>
#include <vector>

#include "exercises/child_session.hpp"

namespace numlab::exercises::sandbox_test {

inline std::string child_script(const std::string& name) { return std::string(NUMLAB_SANDBOX_CHILDREN) + "/" + name; }

// The command that runs children/<name> with the Python the build found, or with sh.
inline std::vector<std::string> python_child(const std::string& name) { return {NUMLAB_PYTHON, child_script(name)}; }
inline std::vector<std::string> sh_child(const std::string& name) { return {"sh", child_script(name)}; }

// The time limit of tests that expect replies (Python may start slowly on a loaded machine), and
// of tests that expect a timeout (from a program that does not reply at all, or from sh).
inline constexpr double generous_limit = 10.0;
inline constexpr double short_limit = 0.5;

// True when no process of the group (or with the pid) exists any more, zombies included.
inline bool group_gone(pid_t group) { return kill(-group, 0) == -1 && errno == ESRCH; }
inline bool process_gone(pid_t pid) { return kill(pid, 0) == -1 && errno == ESRCH; }

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Sanitizer builds start and stop processes slowly: a time limit may be overrun by this much.
inline constexpr double slack_seconds = 3.0;

}  // namespace numlab::exercises::sandbox_test
