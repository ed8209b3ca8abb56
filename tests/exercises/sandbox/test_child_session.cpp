// ChildSession speaks the protocol and turns every way a program can misbehave into a clear
// ChildFailure (or StudentError), within the time limit, leaving no process behind.

#include <catch2/catch.hpp>
#include <chrono>
#include <string>

#include "sandbox_children.hpp"

using namespace numlab::exercises;
using namespace numlab::exercises::sandbox_test;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;

namespace {

// Asks one request of a fresh session running `child` and returns the ChildFailure's message; the
// program's group must be gone right after (not only after the session ends).
std::string failure_of(const std::string& child, double time_limit = generous_limit) {
  ChildSession session("echo", python_child(child), time_limit);
  const pid_t group = session.process_group();
  REQUIRE(group > 0);
  std::string message = "no ChildFailure";
  try {
    session.ask({});
  } catch (const ChildFailure& failure) {
    message = failure.what();
  }
  CHECK(session.process_group() == 0);
  CHECK(group_gone(group));
  return message;
}

}  // namespace

TEST_CASE("a well-behaved program gets the exercise and increasing ids, and its replies come back", "[protocol]") {
  ChildSession session("gepp", python_child("echo.py"), generous_limit);
  session.begin_check();
  for (long long id = 1; id <= 3; ++id) {
    const nlohmann::json reply = session.ask({{"A", {{1.0}}}});
    CHECK(reply.at("id") == id);
    CHECK(reply.at("exercise") == "gepp");
  }
  CHECK(session.seconds_per_request() > 0.0);
  CHECK(session.seconds_per_request() < generous_limit);
  session.begin_check();
  CHECK(session.seconds_per_request() == 0.0);
}

TEST_CASE("the time per request leaves out the program's start-up: the first request is timed again", "[protocol][timing]") {
  ChildSession session("echo", python_child("slow_start.py"), generous_limit);
  session.begin_check();
  const auto start = std::chrono::steady_clock::now();
  const nlohmann::json first = session.ask({});
  CHECK(seconds_since(start) >= 1.0);  // the reply waited for the 1 s import
  CHECK(first.at("seen") == nlohmann::json({1}));
  // The time is that of the same request sent again (same id), once the program was up.
  CHECK(session.seconds_per_request() > 0.0);
  CHECK(session.seconds_per_request() < 0.5);
  CHECK(session.ask({}).at("seen") == nlohmann::json({1, 1, 2}));
  CHECK(session.seconds_per_request() < 0.5);
  // The next check has its own times; the program, still running, is not timed again twice.
  session.begin_check();
  CHECK(session.ask({}).at("seen") == nlohmann::json({1, 1, 2, 3}));
  CHECK(session.seconds_per_request() < 0.5);
}

TEST_CASE("blank lines between replies are skipped, and a CRLF line end is one", "[protocol]") {
  ChildSession session("echo", python_child("blank_lines.py"), generous_limit);
  session.begin_check();
  for (long long id = 1; id <= 3; ++id) CHECK(session.ask({}).at("id") == id);
  CHECK(session.seconds_per_request() > 0.0);
}

TEST_CASE("a crash is reported with its signal, before the request it left unanswered", "[failure]") {
  ChildSession session("echo", python_child("crash.py"), generous_limit);
  session.begin_check();
  const pid_t group = session.process_group();
  CHECK(session.ask({}).at("id") == 1);
  try {
    session.ask({{"crash", true}});
    FAIL("no ChildFailure");
  } catch (const ChildFailure& failure) {
    CHECK(std::string(failure.what()) == "the program was killed by signal SIGSEGV before replying to request 2");
  }
  CHECK(group_gone(group));
  CHECK_THAT(session.take_output(), Contains("about to crash"));
  // The next check starts the program again.
  session.begin_check();
  CHECK(session.process_group() > 0);
  CHECK(session.process_group() != group);
  CHECK(session.ask({}).at("id") == 3);
}

TEST_CASE("a program that never replies is stopped at the time limit, with its group", "[failure][timeout]") {
  const auto start = std::chrono::steady_clock::now();
  const std::string message = failure_of("sleep.py", short_limit);
  const double elapsed = seconds_since(start);
  CHECK(message == "no reply within 0.5 s to request 1 (the program was stopped)");
  CHECK(elapsed >= short_limit);
  CHECK(elapsed < short_limit + slack_seconds);
}

TEST_CASE("a reply that is not JSON is shown, made printable", "[failure]") {
  CHECK(failure_of("garbage.py") == "the reply is not JSON: hello, I am not JSON \\x1b[31mred"
                                    " (stdout is for replies only: print anything else to stderr)");
}

TEST_CASE("a reply with NaN is not JSON, and the message says why", "[failure]") {
  CHECK(failure_of("nan.py") ==
        "the reply is not JSON: {\"id\": 1, \"x\": [1.0, NaN]} (NaN and Infinity are not JSON numbers)");
}

TEST_CASE("a reply to another id names the id expected and the one given", "[failure]") {
  CHECK(failure_of("wrong_id.py") == "the reply has id 2 but request 1 was expected");
}

TEST_CASE("a reply line longer than 16 MiB is refused and the program stopped", "[failure]") {
  CHECK(failure_of("huge_reply.py") == "the reply to request 1 is longer than 16 MiB (the program was stopped)");
}

TEST_CASE("a program that exits after the first request is reported with its exit code", "[failure]") {
  ChildSession session("echo", python_child("exit_after_first.py"), generous_limit);
  session.begin_check();
  const pid_t group = session.process_group();
  CHECK(session.ask({}).at("id") == 1);
  CHECK_THROWS_WITH(session.ask({}), "the program exited with code 0 before replying to request 2");
  CHECK(group_gone(group));
}

TEST_CASE("an error reply is the student's error, not a failure of the program", "[protocol]") {
  ChildSession session("echo", python_child("not_implemented.py"), generous_limit);
  session.begin_check();
  CHECK_THROWS_MATCHES(session.ask({}), StudentError, Catch::Matchers::Message("not implemented"));
  // The program is still there for the next request.
  CHECK(session.process_group() > 0);
  CHECK_THROWS_AS(session.ask({}), StudentError);
}

TEST_CASE("stderr is kept per check up to 64 KiB, the rest counted, without blocking the program", "[output]") {
  ChildSession session("echo", python_child("stderr_flood.py"), generous_limit);
  session.begin_check();
  CHECK(session.ask({}).at("id") == 1);
  const std::string output = session.take_output();
  CHECK_THAT(output, StartsWith(std::string(99, 'x') + "\n"));
  // 1,000,000 bytes written, 65,536 kept.
  CHECK_THAT(output, EndsWith("\n[... 934464 bytes more]"));
  // The cut falls inside a line, which is ended before the note.
  CHECK(output.size() == 65536 + std::string("\n[... 934464 bytes more]").size());
  CHECK(session.take_output().empty());
}
