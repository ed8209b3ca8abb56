// What the program gets (a fresh folder, its own arguments, its own process group, no descriptors
// of numlab's, no core dumps), what it cannot do (start from a bad command, outlive the checker),
// and how a program that cannot run is reported.

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "sandbox_children.hpp"

using namespace numlab::exercises;
using namespace numlab::exercises::sandbox_test;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::Message;
namespace fs = std::filesystem;

namespace {

// Runs a block with another current directory.
class InDirectory {
 public:
  explicit InDirectory(const fs::path& directory) : previous_(fs::current_path()) { fs::current_path(directory); }
  ~InDirectory() { fs::current_path(previous_); }
  InDirectory(const InDirectory&) = delete;
  InDirectory& operator=(const InDirectory&) = delete;

 private:
  fs::path previous_;
};

// A scratch file with the given text and mode, removed at the end of the test.
class ScratchFile {
 public:
  ScratchFile(const std::string& text, fs::perms mode)
      : path_(fs::temp_directory_path() / ("numlab-sandbox-test-" + std::to_string(getpid()))) {
    std::ofstream(path_) << text;
    fs::permissions(path_, mode);
  }
  ~ScratchFile() { fs::remove(path_); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

// Reaps the group's processes that came to this process; true when none is left within `seconds`.
bool group_reaped(pid_t group, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (seconds_since(start) < seconds) {
    const pid_t reaped = waitpid(-group, nullptr, WNOHANG);
    if (reaped < 0) return true;  // none left
    if (reaped == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// A failing test leaves nothing behind either.
void kill_survivors(pid_t group) {
  kill(-group, SIGKILL);
  while (waitpid(-group, nullptr, 0) > 0) {
  }
}

std::string temporary_root() {
  const char* tmpdir = std::getenv("TMPDIR");
  return tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp";
}

}  // namespace

TEST_CASE("the program runs in a fresh, empty temporary folder that is removed afterwards", "[sandbox]") {
  std::string folder;
  {
    ChildSession session("echo", python_child("echo.py"), generous_limit);
    const nlohmann::json reply = session.ask({});
    folder = reply.at("cwd").get<std::string>();
    CHECK(folder == fs::canonical(session.working_directory()).string());
    CHECK_THAT(session.working_directory(), Contains(temporary_root() + "/numlab-exercise-"));
    CHECK(reply.at("listing").empty());
    CHECK(fs::is_directory(folder));
  }
  CHECK_FALSE(fs::exists(folder));
}

TEST_CASE("the program gets only the student's arguments, with files and folders made absolute", "[sandbox]") {
  const fs::path children = NUMLAB_SANDBOX_CHILDREN;
  InDirectory here(children);
  ChildSession session("echo", {NUMLAB_PYTHON, "echo.py", "--verbose", "no-such-file", "."}, generous_limit);
  const nlohmann::json argv = session.ask({}).at("argv");
  const nlohmann::json expected = {(children / "echo.py").string(), "--verbose", "no-such-file", children.string()};
  // Python's argv[0] is the script; fs::absolute keeps "." as a last component, so compare folders.
  REQUIRE(argv.size() == 4);
  CHECK(argv[0] == expected[0]);
  CHECK(argv[1] == expected[1]);
  CHECK(argv[2] == expected[2]);
  CHECK(fs::equivalent(argv[3].get<std::string>(), children));
  CHECK(fs::path(argv[3].get<std::string>()).is_absolute());
}

TEST_CASE("the program has its own process group, no descriptor of numlab's and no core dumps", "[sandbox]") {
  const int inherited = open("/dev/null", O_RDONLY);  // not close-on-exec: the child must not see it
  REQUIRE(inherited >= 0);
  ChildSession session("echo", python_child("echo.py"), generous_limit);
  close(inherited);
  const nlohmann::json reply = session.ask({});
  CHECK(reply.at("pgid") == reply.at("pid"));
  CHECK(reply.at("pgid") == session.process_group());
  CHECK(reply.at("pgid") != getpgrp());
  CHECK(reply.at("open_fds").empty());
  CHECK(reply.at("core_limit") == nlohmann::json{0, 0});
}

TEST_CASE("the program starts with no signal ignored, although numlab ignores SIGPIPE", "[sandbox]") {
  // sh, since Python ignores SIGPIPE itself; the mask is SigIgn of /proc/PID/status.
  ChildSession session("echo", {"sh", "-c", R"(read -r line; mask=$(grep SigIgn /proc/$$/status | cut -f2);
                                              printf '{"id": 1, "ignored": "%s"}\n' "$mask"; cat >/dev/null)"},
                       generous_limit);
  CHECK(session.ask({}).at("ignored") == "0000000000000000");
}

TEST_CASE("a command without a slash is found on PATH and made absolute", "[command]") {
  ChildSession session("echo", {"sh", "-c", "while read line; do :; done"}, generous_limit);
  const std::string program = session.resolved_command().at(0);
  CHECK(fs::path(program).is_absolute());
  CHECK_THAT(program, EndsWith("/sh"));
  CHECK(session.resolved_command().at(1) == "-c");
}

TEST_CASE("a command that cannot be run is bad input, naming the command and the reason", "[command]") {
  CHECK_THROWS_MATCHES(ChildSession("echo", {"numlab-no-such-program"}, generous_limit), std::invalid_argument,
                       Message("exercise check: cannot run 'numlab-no-such-program': not found on PATH"));
  CHECK_THROWS_MATCHES(ChildSession("echo", {"./numlab-no-such-program"}, generous_limit), std::invalid_argument,
                       Message("exercise check: cannot run './numlab-no-such-program': no such file"));
  CHECK_THROWS_MATCHES(ChildSession("echo", {NUMLAB_SANDBOX_CHILDREN}, generous_limit), std::invalid_argument,
                       Message(std::string("exercise check: cannot run '") + NUMLAB_SANDBOX_CHILDREN +
                               "': it is a folder, not a program"));
  CHECK_THROWS_AS(ChildSession("echo", {}, generous_limit), std::invalid_argument);
  CHECK_THROWS_AS(ChildSession("echo", python_child("echo.py"), 0.0), std::invalid_argument);
}

TEST_CASE("a file without execute permission cannot be run", "[command]") {
  const ScratchFile script("#!/bin/sh\n", fs::perms::owner_read | fs::perms::owner_write);
  CHECK_THROWS_MATCHES(ChildSession("echo", {script.path()}, generous_limit), std::invalid_argument,
                       Message("exercise check: cannot run '" + script.path() +
                               "': it is not executable (Permission denied)"));
}

TEST_CASE("an exec failure in the child (a missing #! interpreter) is reported as bad input", "[command]") {
  const ScratchFile script("#!/numlab/no/such/interpreter\n", fs::perms::owner_all);
  CHECK_THROWS_MATCHES(ChildSession("echo", {script.path()}, generous_limit), std::invalid_argument,
                       Message("exercise check: cannot run '" + script.path() +
                               "': its #! interpreter or loader was not found (No such file or directory)"));
}

TEST_CASE("a background grandchild dies with its group when the request times out", "[lifetime]") {
  ChildSession session("echo", sh_child("grandchild.sh"), short_limit);
  const pid_t group = session.process_group();
  const pid_t grandchild = session.ask({}).at("grandchild").get<pid_t>();
  CHECK_FALSE(process_gone(grandchild));
  CHECK_THROWS_WITH(session.ask({{"hang", true}}), "no reply within 0.5 s to request 2 (the program was stopped)");
  CHECK(group_gone(group));
  CHECK(process_gone(grandchild));
}

TEST_CASE("a crash is seen although a background grandchild still holds the program's stdout", "[lifetime]") {
  ChildSession session("echo", sh_child("grandchild.sh"), generous_limit);
  const pid_t group = session.process_group();
  const pid_t grandchild = session.ask({}).at("grandchild").get<pid_t>();
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(session.ask({{"crash", true}}),
                    "the program was killed by signal SIGSEGV before replying to request 2");
  CHECK(seconds_since(start) < slack_seconds);  // not the time limit
  CHECK(group_gone(group));
  CHECK(process_gone(grandchild));
}

TEST_CASE("a background grandchild left by a program that exits does not outlive the session", "[lifetime]") {
  pid_t group = 0;
  pid_t grandchild = 0;
  const auto start = std::chrono::steady_clock::now();
  {
    ChildSession session("echo", sh_child("grandchild.sh"), short_limit);
    group = session.process_group();
    grandchild = session.ask({}).at("grandchild").get<pid_t>();
  }
  // The program exits at the end of its input, so the session need not wait out its 1 s grace.
  CHECK(seconds_since(start) < 1.0 + slack_seconds);
  CHECK(group_gone(group));
  CHECK(process_gone(grandchild));
}

TEST_CASE("a program that ignores the end of its input is killed 1 s after the session ends", "[lifetime]") {
  pid_t group = 0;
  auto start = std::chrono::steady_clock::now();
  {
    ChildSession session("echo", python_child("sleep.py"), short_limit);
    group = session.process_group();
    start = std::chrono::steady_clock::now();
  }
  const double elapsed = seconds_since(start);
  CHECK(elapsed >= 1.0);
  CHECK(elapsed < 1.0 + slack_seconds);
  CHECK(group_gone(group));
}

TEST_CASE("numlab terminated during a check takes the program's whole group with it", "[lifetime]") {
  // The program's processes come to this test process when the checker (a forked copy) dies.
  REQUIRE(prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
  int report[2];
  REQUIRE(pipe(report) == 0);
  const pid_t checker = fork();
  REQUIRE(checker >= 0);
  if (checker == 0) {
    close(report[0]);
    std::signal(SIGTERM, SIG_DFL);  // not the test framework's handler
    try {
      ChildSession session("echo", sh_child("grandchild.sh"), 30.0);
      const pid_t pids[2] = {session.process_group(), session.ask({}).at("grandchild").get<pid_t>()};
      if (write(report[1], pids, sizeof pids) != sizeof pids) _exit(3);
      const std::string& folder = session.working_directory();
      if (write(report[1], folder.data(), folder.size()) != static_cast<ssize_t>(folder.size())) _exit(3);
      close(report[1]);
      session.ask({{"hang", true}});
    } catch (...) {
    }
    _exit(3);  // not reached: SIGTERM ends the checker while it waits
  }
  close(report[1]);
  pid_t pids[2] = {0, 0};
  const bool reported = read(report[0], pids, sizeof pids) == sizeof pids;
  std::string folder(4096, '\0');
  folder.resize(static_cast<std::size_t>(std::max<ssize_t>(0, read(report[0], folder.data(), folder.size()))));
  close(report[0]);
  kill(checker, SIGTERM);
  int status = 0;
  REQUIRE(waitpid(checker, &status, 0) == checker);
  REQUIRE(reported);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  // Reap what was killed (zombies would still count as members of the group).
  CHECK(group_reaped(pids[0], slack_seconds));
  CHECK(group_gone(pids[0]));
  CHECK(process_gone(pids[1]));
  kill_survivors(pids[0]);
  // The program wrote nothing there, so even a signal handler can remove its folder.
  CHECK_THAT(folder, Contains("numlab-exercise-"));
  CHECK_FALSE(fs::exists(folder));
}
