// Processes that leave the program's process group (setsid) or are double-forked do not outlive the
// check: numlab is a child subreaper, so they come to it when their parent dies, and it ends every
// process that came (labs/exercises/descendants.hpp). numlab ended by SIGHUP, SIGQUIT, SIGINT or
// SIGTERM during a check ends them too, removes the program's folder, and dies of that signal.

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "sandbox_children.hpp"

using namespace numlab::exercises;
using namespace numlab::exercises::sandbox_test;
namespace fs = std::filesystem;

namespace {

struct Escapees {
  pid_t escaped = 0;  // setsid: its own session, still a child of the program
  pid_t orphan = 0;   // setsid and double-forked: a child of numlab as soon as its parent exited
};

Escapees escapees_of(ChildSession& session) {
  const nlohmann::json reply = session.ask({});
  return {reply.at("escaped").get<pid_t>(), reply.at("orphan").get<pid_t>()};
}

// setsid(1) calls setsid() after the shell has told its pid: wait (up to 5 s) until it has.
bool leads_its_own_session(pid_t pid) {
  for (int wait = 0; wait < 500 && getsid(pid) != pid; ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return getsid(pid) == pid;
}

// Ends what a failed check left, so that one failure does not leave sleeping processes behind.
void end_survivors(const Escapees& escapees) {
  for (const pid_t pid : {escapees.escaped, escapees.orphan}) {
    if (pid <= 0 || process_gone(pid)) continue;
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }
}

}  // namespace

TEST_CASE("a grandchild that calls setsid, and a double-forked one, do not outlive the session", "[lifetime]") {
  Escapees escapees;
  {
    ChildSession session("echo", sh_child("escaping_grandchildren.sh"), generous_limit);
    escapees = escapees_of(session);
    CHECK_FALSE(process_gone(escapees.escaped));
    CHECK_FALSE(process_gone(escapees.orphan));
    // Out of the program's group and session.
    CHECK(leads_its_own_session(escapees.escaped));
    CHECK(leads_its_own_session(escapees.orphan));
  }
  CHECK(process_gone(escapees.escaped));
  CHECK(process_gone(escapees.orphan));
  end_survivors(escapees);
}

TEST_CASE("a grandchild that calls setsid does not outlive a program stopped at the time limit", "[lifetime]") {
  ChildSession session("echo", sh_child("escaping_grandchildren.sh"), short_limit);
  const Escapees escapees = escapees_of(session);
  CHECK_THROWS_WITH(session.ask({{"hang", true}}), "no reply within 0.5 s to request 2 (the program was stopped)");
  CHECK(process_gone(escapees.escaped));
  CHECK(process_gone(escapees.orphan));
  end_survivors(escapees);
}

TEST_CASE("numlab ended by SIGHUP, SIGQUIT, SIGINT or SIGTERM during a check ends every process and removes the folder",
          "[lifetime]") {
  // What the checker (a forked copy) fails to end would come to this test process.
  REQUIRE(prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
  for (const int signal : {SIGHUP, SIGQUIT, SIGINT, SIGTERM}) {
    int report[2];
    REQUIRE(pipe(report) == 0);
    const pid_t checker = fork();
    REQUIRE(checker >= 0);
    if (checker == 0) {
      close(report[0]);
      for (const int other : {SIGHUP, SIGQUIT, SIGINT, SIGTERM}) std::signal(other, SIG_DFL);  // not the framework's
      try {
        ChildSession session("echo", sh_child("escaping_grandchildren.sh"), 30.0);
        const Escapees escapees = escapees_of(session);
        const std::string& folder = session.working_directory();
        if (write(report[1], &escapees, sizeof escapees) != sizeof escapees) _exit(3);
        if (write(report[1], folder.data(), folder.size()) != static_cast<ssize_t>(folder.size())) _exit(3);
        close(report[1]);
        session.ask({{"hang", true}});
      } catch (...) {
      }
      _exit(3);  // not reached: the signal ends the checker while it waits
    }
    close(report[1]);
    Escapees escapees;
    const bool reported = read(report[0], &escapees, sizeof escapees) == sizeof escapees;
    std::string folder(4096, '\0');
    folder.resize(static_cast<std::size_t>(std::max<ssize_t>(0, read(report[0], folder.data(), folder.size()))));
    close(report[0]);
    CHECK(leads_its_own_session(escapees.escaped));
    CHECK(leads_its_own_session(escapees.orphan));
    kill(checker, signal);
    int status = 0;
    REQUIRE(waitpid(checker, &status, 0) == checker);
    INFO("signal " << sigabbrev_np(signal));
    REQUIRE(reported);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal);
    CHECK_FALSE(WCOREDUMP(status));
    CHECK(process_gone(escapees.escaped));
    CHECK(process_gone(escapees.orphan));
    // The program wrote orphan.pid there: the folder is removed with what is in it.
    CHECK(folder.find("numlab-exercise-") != std::string::npos);
    CHECK_FALSE(fs::exists(folder));
    end_survivors(escapees);
  }
}
