// run_checks (checker.hpp) over a ChildSession: what a misbehaving program does to each check's
// status, and that the battery goes on (or stops asking) as the contract says.

#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "sandbox_children.hpp"

using namespace numlab::exercises;
using namespace numlab::exercises::sandbox_test;
using Catch::Matchers::Contains;

namespace {

// A check that asks one request and passes when the reply echoes its id.
Check asking(std::string name, nlohmann::json request) {
  return Check{std::move(name), 1, [request](Session& session) {
                 const nlohmann::json reply = session.ask(request);
                 return reply.contains("id") ? Verdict::pass() : Verdict::fail("no id");
               }};
}

Exercise tiny_exercise(std::vector<Check> checks) {
  return Exercise{"echo", "answers with its id", "Reply with the request's id.", Stubs{}, [checks](const Variant&) { return checks; }};
}

}  // namespace

TEST_CASE("a crash makes its check an error and the next check runs on a restarted program", "[checks]") {
  ChildSession session("echo", python_child("crash.py"), generous_limit);
  const Exercise exercise = tiny_exercise(
      {asking("answers first", {}), asking("crashes", {{"crash", true}}), asking("answers after a restart", {})});
  const std::vector<CheckResult> results = run_checks(exercise, session);
  REQUIRE(results.size() == 3);
  CHECK(results[0].status == CheckStatus::pass);
  CHECK(results[1].status == CheckStatus::error);
  CHECK(results[1].message == "the program was killed by signal SIGSEGV before replying to request 2");
  CHECK_THAT(results[1].output, Contains("about to crash"));
  CHECK(results[2].status == CheckStatus::pass);
  CHECK(results[2].output.empty());
}

TEST_CASE("a program that never replies costs at most max_failures_in_a_row time limits", "[checks][timeout]") {
  constexpr double limit = 0.3;
  ChildSession session("echo", python_child("sleep.py"), limit);
  std::vector<Check> checks;
  for (int i = 1; i <= max_failures_in_a_row + 2; ++i) checks.push_back(asking("check " + std::to_string(i), {}));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CheckResult> results = run_checks(tiny_exercise(checks), session);
  const double elapsed = seconds_since(start);
  REQUIRE(results.size() == checks.size());
  for (int i = 0; i < max_failures_in_a_row; ++i) {
    CHECK(results[i].status == CheckStatus::error);
    CHECK(results[i].message ==
          "no reply within 0.3 s to request " + std::to_string(i + 1) + " (the program was stopped)");
  }
  for (std::size_t i = max_failures_in_a_row; i < results.size(); ++i) {
    CHECK(results[i].status == CheckStatus::error);
    CHECK_THAT(results[i].message, Contains("not run"));
  }
  CHECK(elapsed >= max_failures_in_a_row * limit);
  CHECK(elapsed < max_failures_in_a_row * limit + slack_seconds);
}

TEST_CASE("an error reply fails the check with the program's own message", "[checks]") {
  ChildSession session("echo", python_child("not_implemented.py"), generous_limit);
  const std::vector<CheckResult> results = run_checks(tiny_exercise({asking("solves", {})}), session);
  REQUIRE(results.size() == 1);
  CHECK(results[0].status == CheckStatus::fail);
  CHECK(results[0].message == "your program replied with an error: not implemented");
}

TEST_CASE("a reply with NaN makes its check an error, not a fail", "[checks]") {
  ChildSession session("echo", python_child("nan.py"), generous_limit);
  const std::vector<CheckResult> results = run_checks(tiny_exercise({asking("solves", {})}), session);
  REQUIRE(results.size() == 1);
  CHECK(results[0].status == CheckStatus::error);
  CHECK_THAT(results[0].message, Contains("NaN and Infinity are not JSON numbers"));
}
