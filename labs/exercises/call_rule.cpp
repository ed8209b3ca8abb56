#include "exercises/call_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace numlab::exercises {

namespace {

// "numpy.linalg.solve 12 times and numpy.linalg.inv once", the most called first.
std::string called(const LibraryCalls& calls) {
  std::vector<std::pair<std::string, long long>> counts(calls.counts.begin(), calls.counts.end());
  std::stable_sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string text;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const auto& [name, count] = counts[k];
    text += k == 0 ? "" : k + 1 == counts.size() ? " and " : ", ";
    text += name + (count == 1 ? " once" : count == 2 ? " twice" : fmt::format(" {} times", count));
  }
  return text;
}

}  // namespace

std::optional<Diagnosis> library_call_diagnosis(const LibraryCalls& calls, const ForbiddenCalls& forbidden) {
  if (calls.counts.empty()) return std::nullopt;
  return Diagnosis{"library_call", Specificity::forbidden, fmt::format("called {}: {}", called(calls), forbidden.asks)};
}

void CallRule::after_check(Session& session, const std::vector<CheckResult>& results) {
  if (calls_.empty() || results.empty()) return;
  const LibraryCalls during = session.take_library_calls();
  noticed_.add(during);
  if (!during.counts.empty()) calling_checks_.push_back(results.size() - 1);
}

void CallRule::finish(std::vector<CheckResult>& results) const {
  if (calls_.empty() || noticed_.watched.empty()) return;
  const std::optional<Diagnosis> diagnosis = library_call_diagnosis(noticed_, calls_);
  const bool some_passed = std::any_of(results.begin(), results.end(),
                                       [](const CheckResult& result) { return result.status == CheckStatus::pass; });
  if (!diagnosis && !some_passed) return;
  for (const std::size_t k : calling_checks_) {
    if (results[k].status != CheckStatus::pass) results[k].diagnosis = more_specific(results[k].diagnosis, diagnosis);
  }
  CheckResult result;
  result.name = call_rule_check_name;
  result.task_id = 0;  // a rule of the whole exercise, not of one task
  result.diagnosis = diagnosis;
  result.status = diagnosis ? CheckStatus::fail : CheckStatus::pass;
  if (diagnosis) result.message = fmt::format("your program called {}; TASK.md: \"{}\"", called(noticed_), calls_.rule);
  results.push_back(std::move(result));
}

}  // namespace numlab::exercises
