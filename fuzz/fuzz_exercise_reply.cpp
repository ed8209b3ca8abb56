// Fuzzes the replies of a student's program to `numlab exercise check` (docs/fuzzing.md): the
// first byte picks the exercise, the second one of its checks, and the rest are the reply lines,
// one per request in turn. Every reply is read the way the real session reads it (a JSON object,
// its id supplied, "error" raised as the student's error) and then the check uses it. A check may
// end with a verdict or with the three exceptions that make a check `fail` or `error`; anything
// else escaping, a crash, undefined behaviour or a hang is a finding.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "exercises/exercise.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"

namespace {

using namespace numlab::exercises;

// Answers each request with the next of the fuzzed lines; past the last line the program "exited".
class ReplaySession : public Session {
 public:
  explicit ReplaySession(std::string_view text) {
    std::size_t start = 0;
    while (start <= text.size() && lines_.size() < 4096) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      lines_.emplace_back(text.substr(start, end - start));
      start = end + 1;
    }
  }

  nlohmann::json ask(nlohmann::json request) override {
    request["id"] = ++id_;
    if (next_ >= lines_.size()) throw ChildFailure("the program exited");
    nlohmann::json reply = nlohmann::json::parse(lines_[next_++], nullptr, false);
    if (reply.is_discarded() || !reply.is_object()) throw ChildFailure("the reply is not a JSON object");
    reply["id"] = id_;
    if (reply.contains("error")) throw StudentError(reply["error"].dump());
    return reply;
  }
  double seconds_per_request() const override { return 0.0; }

 private:
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  long long id_ = 0;
};

const std::vector<Check>& checks_of(const Exercise& exercise) {
  static std::map<std::string, std::vector<Check>> batteries;
  auto found = batteries.find(exercise.name);
  if (found == batteries.end()) found = batteries.emplace(exercise.name, exercise.battery(Variant())).first;
  return found->second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto& exercises = all_exercises();
  const Exercise& exercise = exercises[data[0] % exercises.size()];
  const auto& checks = checks_of(exercise);
  if (checks.empty()) return 0;
  const Check& check = checks[data[1] % checks.size()];
  ReplaySession session(std::string_view(reinterpret_cast<const char*>(data + 2), size - 2));
  try {
    (void)check.run(session);
  } catch (const ChildFailure&) {
  } catch (const StudentError&) {
  } catch (const ReplyError&) {
  }
  return 0;
}
