#include "exercises/descendants.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>

namespace numlab::exercises {

namespace {

// ---------------------------------------------------------------------------------------------
// The running programs' leaders: a fixed table, read in signal handlers.

constexpr int max_running = 64;
std::atomic<pid_t> running_leaders[max_running];

bool is_running_leader(pid_t pid) {
  for (const std::atomic<pid_t>& leader : running_leaders)
    if (leader.load() == pid) return true;
  return false;
}

// ---------------------------------------------------------------------------------------------
// /proc, read with system calls only.

// "123" -> 123; anything else (".", "self", "123x") -> 0.
pid_t pid_of_name(const char* name) {
  long value = 0;
  for (const char* c = name; *c != '\0'; ++c) {
    if (*c < '0' || *c > '9' || value > 1'000'000'000) return 0;
    value = value * 10 + (*c - '0');
  }
  return static_cast<pid_t>(value);
}

// "/proc/PID/stat" written into `path` (at least 32 bytes).
void stat_path(pid_t pid, char* path) {
  char digits[16];
  int count = 0;
  for (long value = pid; value > 0 || count == 0; value /= 10) digits[count++] = static_cast<char>('0' + value % 10);
  const char prefix[] = "/proc/";
  int at = 0;
  for (const char c : prefix)
    if (c != '\0') path[at++] = c;
  while (count > 0) path[at++] = digits[--count];
  for (const char c : "/stat") path[at++] = c;  // the terminating '\0' included
}

// The parent of `pid` from /proc/PID/stat ("PID (COMM) STATE PPID ...", COMM may hold ") "), or -1.
pid_t parent_of(pid_t pid) {
  char path[32];
  stat_path(pid, path);
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  char text[512];
  const ssize_t got = read(fd, text, sizeof text);
  close(fd);
  ssize_t close_paren = got - 1;
  while (close_paren >= 0 && text[close_paren] != ')') --close_paren;
  if (close_paren < 0 || close_paren + 4 >= got) return -1;
  long parent = 0;
  for (ssize_t at = close_paren + 4; at < got && text[at] >= '0' && text[at] <= '9'; ++at) parent = parent * 10 + (text[at] - '0');
  return static_cast<pid_t>(parent);
}

// Up to `capacity` children of this process, killed with SIGKILL, their pids in `found`.
int kill_children(bool spare_running_programs, pid_t* found, int capacity) {
  const int proc = open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (proc < 0) return 0;
  const pid_t self = getpid();
  int count = 0;
  alignas(dirent64) char buffer[4096];
  for (ssize_t got = 0; count < capacity && (got = getdents64(proc, buffer, sizeof buffer)) > 0;) {
    for (ssize_t at = 0; at < got && count < capacity;) {
      const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
      at += entry->d_reclen;
      const pid_t pid = pid_of_name(entry->d_name);
      if (pid <= 0 || parent_of(pid) != self || (spare_running_programs && is_running_leader(pid))) continue;
      kill(pid, SIGKILL);
      found[count++] = pid;
    }
  }
  close(proc);
  return count;
}

// ---------------------------------------------------------------------------------------------
// Removing a folder without recursion: descend into a subfolder that is not empty, empty it, go
// back up, and try again.

bool is_dot_or_dot_dot(const char* name) { return name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0')); }

// Removes what it can in `folder`; returns an open subfolder that is not empty yet, or -1.
int clear_folder(int folder) {
  lseek(folder, 0, SEEK_SET);
  alignas(dirent64) char buffer[4096];
  for (ssize_t got = 0; (got = getdents64(folder, buffer, sizeof buffer)) > 0;) {
    for (ssize_t at = 0; at < got;) {
      const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
      at += entry->d_reclen;
      const char* name = entry->d_name;
      if (is_dot_or_dot_dot(name)) continue;
      if (unlinkat(folder, name, 0) == 0 || unlinkat(folder, name, AT_REMOVEDIR) == 0) continue;
      if (errno != ENOTEMPTY && errno != EEXIST) continue;
      const int subfolder = openat(folder, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
      if (subfolder >= 0) return subfolder;
    }
  }
  return -1;
}

}  // namespace

void register_running_program(pid_t leader) {
  for (std::atomic<pid_t>& slot : running_leaders) {
    pid_t empty = 0;
    if (slot.compare_exchange_strong(empty, leader)) return;
  }
}

void unregister_running_program(pid_t leader) {
  for (std::atomic<pid_t>& slot : running_leaders) {
    pid_t expected = leader;
    slot.compare_exchange_strong(expected, 0);
  }
}

int end_adopted_children(bool spare_running_programs) {
  int ended = 0;
  for (int round = 0; round < 10'000; ++round) {
    pid_t found[256];
    const int count = kill_children(spare_running_programs, found, 256);
    if (count == 0) break;
    // Reaping one makes its own children ours: the next round finds them.
    for (int k = 0; k < count; ++k) {
      while (waitpid(found[k], nullptr, 0) < 0 && errno == EINTR) {
      }
    }
    ended += count;
  }
  return ended;
}

bool remove_tree(const char* path) {
  int folder = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  int depth = 0;
  for (int step = 0; folder >= 0 && step < 100'000; ++step) {
    const int subfolder = clear_folder(folder);
    if (subfolder < 0 && depth == 0) break;
    const int next = subfolder >= 0 ? subfolder : openat(folder, "..", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    depth += subfolder >= 0 ? 1 : -1;
    close(folder);
    folder = next;
  }
  if (folder >= 0) close(folder);
  return rmdir(path) == 0 || errno == ENOENT;
}

}  // namespace numlab::exercises
