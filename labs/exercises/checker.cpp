#include "exercises/checker.hpp"

#include <fmt/format.h>

#include "exercises/call_rule.hpp"
#include "exercises/reply_fields.hpp"

namespace numlab::exercises {

std::string to_string(CheckStatus status) {
  switch (status) {
    case CheckStatus::pass: return "pass";
    case CheckStatus::fail: return "fail";
    case CheckStatus::error: return "error";
  }
  return "error";
}

namespace {

// Passes each request on to the real session and keeps it, with the reply (or why there was none)
// and what the check said it expected: the makings of a replay file.
class RecordingSession final : public Session {
 public:
  RecordingSession(std::string exercise, Session& inner) : exercise_(std::move(exercise)), inner_(inner) {}

  nlohmann::json ask(nlohmann::json request) override {
    Exchange exchange;
    exchange.request = request;
    exchange.request["exercise"] = exercise_;
    exchange.request["id"] = static_cast<long long>(exchanges.size()) + 1;
    exchanges.push_back(std::move(exchange));
    try {
      nlohmann::json reply = inner_.ask(std::move(request));
      exchanges.back().reply = reply;
      exchanges.back().reply["id"] = exchanges.back().request["id"];  // the id the file's request carries
      return reply;
    } catch (const std::exception& error) {
      exchanges.back().error = error.what();
      throw;
    }
  }
  double seconds_per_request() const override { return inner_.seconds_per_request(); }
  void begin_check() override { inner_.begin_check(); }
  std::string take_output() override { return inner_.take_output(); }
  void expect(Expectation expected) override {
    if (!exchanges.empty()) exchanges.back().expected = std::move(expected);
  }

  std::vector<Exchange> exchanges;

 private:
  std::string exercise_;
  Session& inner_;
};

// One check: its verdict, or what stopped the program from giving one.
CheckResult run_one(const std::string& exercise, const Check& check, Session& inner, bool& child_failed) {
  CheckResult result{check.name, check.task_id, CheckStatus::error, "", "", "", 0.0, {}, {}, "", std::nullopt};
  child_failed = false;
  RecordingSession session(exercise, inner);
  session.begin_check();
  try {
    const Verdict verdict = check.run(session);
    result.status = verdict.passed ? CheckStatus::pass : CheckStatus::fail;
    result.message = verdict.message;
    result.hint = verdict.hint;
    result.references = verdict.references;
    if (!verdict.passed) result.diagnosis = verdict.diagnosis;
    if (!verdict.passed) result.trace = verdict.trace;
  } catch (const StudentError& error) {
    result.status = CheckStatus::fail;
    result.message = fmt::format("your program replied with an error: {}", error.what());
  } catch (const ReplyError& error) {
    result.message = fmt::format("the reply is not a usable answer: {}", error.what());
  } catch (const ChildFailure& error) {
    result.message = error.what();
    child_failed = true;
  } catch (const std::exception& error) {
    // A reply shaped in a way no check foresaw: still an error of this check, never a crash of the
    // checker (fuzz/fuzz_exercise_reply.cpp hunts for these).
    result.message = fmt::format("numlab could not use the reply: {}", error.what());
  }
  result.seconds_per_request = session.seconds_per_request();
  result.output = session.take_output();
  result.exchanges = std::move(session.exchanges);
  return result;
}

}  // namespace

std::vector<CheckResult> run_checks(const Exercise& exercise, Session& session, const Variant& variant) {
  std::vector<CheckResult> results;
  int failures_in_a_row = 0;
  CallRule call_rule(exercise.name);  // forbidden library calls (call_rule.hpp)
  for (const Check& check : exercise.battery(variant)) {
    if (failures_in_a_row >= max_failures_in_a_row) {
      results.push_back({check.name, check.task_id, CheckStatus::error,
                         fmt::format("not run: the program gave no reply in the {} checks before", failures_in_a_row),
                         "", "", 0.0, {}, {}, "", std::nullopt});
      continue;
    }
    bool child_failed = false;
    results.push_back(run_one(exercise.name, check, session, child_failed));
    call_rule.after_check(session, results);
    failures_in_a_row = child_failed ? failures_in_a_row + 1 : 0;
  }
  call_rule.finish(results);
  return results;
}

CheckResult run_check(const Exercise& exercise, const Check& check, Session& session) {
  bool child_failed = false;
  return run_one(exercise.name, check, session, child_failed);
}

std::optional<Diagnosis> overall_diagnosis(const std::vector<CheckResult>& results) {
  std::optional<Diagnosis> best;
  for (const CheckResult& result : results) {
    if (result.status != CheckStatus::pass) best = more_specific(best, result.diagnosis);
  }
  return best;
}

std::string explanation(const CheckResult& result) {
  if (result.diagnosis) return "Diagnosis: " + result.diagnosis->evidence;
  if (!result.hint.empty()) return "Hint: " + result.hint;
  return "";
}

}  // namespace numlab::exercises
