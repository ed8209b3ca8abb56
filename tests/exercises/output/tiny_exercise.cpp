#include "tiny_exercise.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "exercises/session.hpp"

namespace numlab::test {

using exercises::Check;
using exercises::Session;
using exercises::Verdict;

namespace {

// The reply's "sum" against the exact sum of `values` (small integers: exact in doubles).
Check sum_check(const std::string& name, int task_id, std::vector<double> values) {
  return Check{name, task_id, [values](Session& session) {
                 const nlohmann::json reply = session.ask({{"v", values}});
                 if (!reply.contains("sum") || !reply["sum"].is_number())
                   return Verdict::fail("the reply has no number \"sum\"");
                 const double sum = reply["sum"].get<double>();
                 const double exact = std::accumulate(values.begin(), values.end(), 0.0);
                 if (sum == exact) return Verdict::pass();
                 return Verdict::fail(fmt::format("sum is {}, the exact sum is {}", sum, exact),
                                      "did you skip the first element?");
               }};
}

}  // namespace

exercises::Exercise tiny_exercise() {
  exercises::Exercise exercise;
  exercise.name = "tiny-sum";
  exercise.summary = "The sum of a list (a test exercise)";
  exercise.task = "# tiny-sum\n\nReply `sum`: the sum of the request's list `v`.\n";
  exercise.stubs.python = "raise NotImplementedError(\"not implemented: reply {'sum': ...}\")\n";
  exercise.stubs.cpp = "throw std::runtime_error(\"not implemented: reply {\\\"sum\\\": ...}\");\n";
  exercise.stubs.octave = "error('not implemented: reply struct(''sum'', ...)');\n";
  exercise.battery = [](const exercises::Variant&) {
    return std::vector<Check>{sum_check("the sum of three numbers is exact", 1, {1, 2, 3}),
                              sum_check("the sum of one number is that number", 1, {7}),
                              sum_check("the sum of an empty list is 0", 2, {})};
  };
  return exercise;
}

exercises::Stubs tiny_solutions() {
  return {"v = np.array(request[\"v\"], dtype=float)\nreturn {\"sum\": v.sum(), \"v\": v}\n",
          "double sum = 0;\nfor (double v : numlab::exercise::vector(request[\"v\"])) sum += v;\nreturn {{\"sum\", sum}};\n",
          "reply = struct('sum', sum(request.v));\n"};
}

}  // namespace numlab::test
