// The forbidden library calls (labs/exercises/forbidden_calls.hpp, call_watch.hpp, call_rule.hpp):
// each list stated in its TASK.md, the watch's files and log, and the rule's verdicts. The watch
// itself, run by real Python and Octave programs, is tested end to end by check_forbidden.py.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "exercises/call_rule.hpp"
#include "exercises/call_watch.hpp"
#include "exercises/child_process.hpp"
#include "exercises/exercise.hpp"

using namespace numlab::exercises;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// The text with every run of white space made one space (a rule may wrap in TASK.md).
std::string flat(const std::string& text) {
  std::istringstream words(text);
  std::string word, out;
  while (words >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

// TASK.md's "## Library functions" section, up to the next heading.
std::string library_section(const std::string& task) {
  const std::size_t start = task.find("## Library functions");
  if (start == std::string::npos) return "";
  const std::size_t end = task.find("\n## ", start + 1);
  return task.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

struct TemporaryFolder {
  fs::path path;
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "numlab-forbidden-XXXXXX").string();
    REQUIRE(mkdtemp(pattern.data()) != nullptr);
    path = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

void append(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::app | std::ios::binary);
  out << text;
}

// A session whose watch "noticed" the given calls, one LibraryCalls per take.
class NoticingSession final : public Session {
 public:
  explicit NoticingSession(std::vector<LibraryCalls> takes) : takes_(std::move(takes)) {}
  nlohmann::json ask(nlohmann::json) override { return nlohmann::json::object(); }
  double seconds_per_request() const override { return 0.0; }
  LibraryCalls take_library_calls() override {
    if (next_ == takes_.size()) return {};
    return takes_[next_++];
  }

 private:
  std::vector<LibraryCalls> takes_;
  std::size_t next_ = 0;
};

CheckResult check_result(const std::string& name, CheckStatus status, std::optional<Diagnosis> diagnosis = {}) {
  CheckResult result;
  result.name = name;
  result.status = status;
  result.diagnosis = std::move(diagnosis);
  return result;
}

LibraryCalls calls(std::set<std::string> watched, std::map<std::string, long long> counts) {
  LibraryCalls noticed;
  noticed.watched = std::move(watched);
  noticed.counts = std::move(counts);
  return noticed;
}

}  // namespace

TEST_CASE("each exercise's TASK.md states its rule and names every function it forbids") {
  for (const char* name : {"gepp", "gauss-seidel", "inverse2x2", "polyfit", "jansen-jacobian", "jansen10-jacobian",
                           "jansen-newton", "mustang-newton"}) {
    INFO(name);
    CHECK_FALSE(forbidden_calls(name).python.empty());  // a key misspelt in the table forbids nothing
  }
  for (const Exercise& exercise : all_exercises()) {
    const ForbiddenCalls& forbidden = forbidden_calls(exercise.name);
    if (forbidden.empty()) continue;
    INFO(exercise.name);
    const std::string section = library_section(exercise.task);
    REQUIRE_FALSE(section.empty());
    CHECK_THAT(flat(section), Contains(flat(forbidden.rule)));
    for (const std::string& entry : forbidden.python) CHECK_THAT(section, Contains("`" + python_call_name(entry) + "`"));
    for (const std::string& function : forbidden.octave) CHECK_THAT(section, Contains("`" + function + "`"));
  }
  CHECK(forbidden_calls("no-such-exercise").empty());
  CHECK(python_call_name("numpy.polynomial:Polynomial.fit") == "numpy.polynomial.Polynomial.fit");
}

TEST_CASE("the numerical exercises allow what their references use") {
  const auto forbids = [](const std::string& exercise, const std::string& entry) {
    const std::vector<std::string>& python = forbidden_calls(exercise).python;
    return std::find(python.begin(), python.end(), entry) != python.end();
  };
  CHECK(forbids("gepp", "numpy.linalg:solve"));
  CHECK_FALSE(forbids("jansen-newton", "numpy.linalg:solve"));  // the linear step of Newton
  CHECK_FALSE(forbids("polyfit", "numpy.linalg:lstsq"));        // the scaled Vandermonde's least squares
  CHECK(forbids("polyfit", "numpy:polyfit"));
}

TEST_CASE("the watch's files and the environment that loads them") {
  TemporaryFolder folder;
  const fs::path watch = folder.path / "watch";
  const std::vector<std::string> environment = install_call_watch(watch.string(), forbidden_calls("gepp"));
  CHECK(std::find(environment.begin(), environment.end(), "NUMLAB_CALL_LOG=" + (watch / "calls.log").string()) !=
        environment.end());
  const auto setting = [&](const std::string& name) {
    for (const std::string& entry : environment)
      if (entry.rfind(name + "=", 0) == 0) return entry.substr(name.size() + 1);
    return std::string("(unset)");
  };
  CHECK_THAT(setting("PYTHONPATH"), StartsWith((watch / "python").string()));
  CHECK(setting("OCTAVE_SITE_INITFILE") == (watch / "octave" / "init.m").string());
  CHECK(fs::exists(watch / "python" / "sitecustomize.py"));
  std::ifstream listed(watch / "python" / "forbidden.txt");
  std::string line;
  std::vector<std::string> entries;
  while (std::getline(listed, line)) entries.push_back(line);
  CHECK(entries == forbidden_calls("gepp").python);
  for (const std::string& function : forbidden_calls("gepp").octave) {
    CHECK(fs::exists(watch / "octave" / "wrappers" / (function + ".m")));
  }
  CHECK(fs::exists(watch / "octave" / "support" / "numlab_watched_call.m"));

  // No Octave function is forbidden in the Jacobian exercises: Octave is not watched there.
  const fs::path jacobian = folder.path / "jacobian";
  const std::vector<std::string> python_only = install_call_watch(jacobian.string(), forbidden_calls("jansen-jacobian"));
  CHECK(std::none_of(python_only.begin(), python_only.end(),
                     [](const std::string& entry) { return entry.rfind("OCTAVE_SITE_INITFILE=", 0) == 0; }));
  CHECK_FALSE(fs::exists(jacobian / "octave"));
  CHECK(install_call_watch((folder.path / "none").string(), forbidden_calls("no-such-exercise")).empty());
  CHECK_FALSE(fs::exists(folder.path / "none"));
}

TEST_CASE("the call log is read line by line, a line still being written left for the next read") {
  TemporaryFolder folder;
  const std::string log = call_log_path(folder.path.string());
  std::uintmax_t offset = 0;
  CHECK(read_call_log(log, offset).counts.empty());  // no log yet
  append(log, "+python\nnumpy.linalg.solve\nscipy.linalg.lu\nnumpy.linalg.solve\nnumpy.linalg.so");
  LibraryCalls first = read_call_log(log, offset);
  CHECK(first.watched == std::set<std::string>{"python"});
  CHECK(first.counts == std::map<std::string, long long>{{"numpy.linalg.solve", 2}, {"scipy.linalg.lu", 1}});
  append(log, "lve\n+octave\n");
  LibraryCalls second = read_call_log(log, offset);
  CHECK(second.watched == std::set<std::string>{"octave"});
  CHECK(second.counts == std::map<std::string, long long>{{"numpy.linalg.solve", 1}});
  CHECK(read_call_log(log, offset).counts.empty());
  first.add(second);
  CHECK(first.counts.at("numpy.linalg.solve") == 3);
  CHECK(first.watched.size() == 2);
}

TEST_CASE("the rule fails on a forbidden call, and the failing checks that made one are diagnosed with it") {
  // Check 1 failed (its own detector fired) and called solve 3 times; check 2 passed and called it twice.
  NoticingSession session({calls({"python"}, {{"numpy.linalg.solve", 3}}), calls({}, {{"numpy.linalg.solve", 2}})});
  CallRule rule("gepp");
  std::vector<CheckResult> results;
  results.push_back(check_result("trace", CheckStatus::fail, Diagnosis{"no_pivoting", Specificity::exact, "row 2"}));
  rule.after_check(session, results);
  results.push_back(check_result("random systems", CheckStatus::pass));
  rule.after_check(session, results);
  rule.finish(results);

  REQUIRE(results.size() == 3);
  const std::string evidence = "called numpy.linalg.solve 5 times: this exercise asks for elimination by hand";
  REQUIRE(results[0].diagnosis);
  CHECK(results[0].diagnosis->cause == "library_call");
  CHECK(results[0].diagnosis->evidence == evidence);
  CHECK_FALSE(results[1].diagnosis);
  CHECK(results[2].name == call_rule_check_name);
  CHECK(results[2].status == CheckStatus::fail);
  CHECK(results[2].message == "your program called numpy.linalg.solve 5 times; TASK.md: \"" +
                                  forbidden_calls("gepp").rule + "\"");
  REQUIRE(overall_diagnosis(results));
  CHECK(overall_diagnosis(results)->specificity == Specificity::forbidden);
  CHECK(overall_diagnosis(results)->evidence == evidence);
}

TEST_CASE("the rule passes a watched program that passed a check and called nothing forbidden; else it is absent") {
  // Checks of the given statuses, each after_check taking the next of `takes`.
  const auto run = [](std::vector<LibraryCalls> takes, std::vector<CheckStatus> statuses) {
    NoticingSession session(std::move(takes));
    CallRule rule("polyfit");
    std::vector<CheckResult> results;
    for (const CheckStatus status : statuses) {
      results.push_back(check_result("fit", status, Diagnosis{"degree_off_by_one", Specificity::exact, "e"}));
      rule.after_check(session, results);
    }
    rule.finish(results);
    return results;
  };
  const std::vector<CheckResult> kept = run({calls({"octave"}, {})}, {CheckStatus::pass});
  REQUIRE(kept.size() == 2);
  CHECK(kept[1].name == call_rule_check_name);
  CHECK(kept[1].status == CheckStatus::pass);
  CHECK(run({calls({"octave"}, {})}, {CheckStatus::fail}).size() == 1);  // nothing passed: no rule shown kept
  CHECK(run({}, {CheckStatus::pass}).size() == 1);                       // not watched (C++): no rule check
  // A call during the second failing check only: the first keeps its own diagnosis.
  const std::vector<CheckResult> broken =
      run({calls({"octave"}, {}), calls({}, {{"polyfit", 1}})}, {CheckStatus::fail, CheckStatus::fail});
  REQUIRE(broken.size() == 3);
  CHECK(broken[0].diagnosis->cause == "degree_off_by_one");
  CHECK(broken[1].diagnosis->cause == "library_call");
  CHECK(broken[2].status == CheckStatus::fail);
  CHECK(broken[2].diagnosis->evidence == broken[1].diagnosis->evidence);
  // Two functions, counted in words.
  const std::optional<Diagnosis> two = library_call_diagnosis(
      calls({"python"}, {{"numpy.polyfit", 1}, {"numpy.polynomial.Polynomial.fit", 2}}), forbidden_calls("polyfit"));
  REQUIRE(two);
  CHECK_THAT(two->evidence, StartsWith("called numpy.polynomial.Polynomial.fit twice and numpy.polyfit once: "));
}

TEST_CASE("a child gets numlab's environment with the watch's settings over it") {
  setenv("NUMLAB_TEST_KEPT", "kept", 1);
  setenv("NUMLAB_TEST_REPLACED", "old", 1);
  ChildProcess child("/bin/sh", {"-c", "echo \"$NUMLAB_TEST_KEPT $NUMLAB_TEST_REPLACED $NUMLAB_TEST_ADDED\""},
                     fs::temp_directory_path().string(), {"NUMLAB_TEST_REPLACED=new", "NUMLAB_TEST_ADDED=added"});
  CappedText errors(1024);
  std::string line;
  REQUIRE(child.exchange("", ChildProcess::Clock::now() + std::chrono::seconds(10), 1024, line, errors) ==
          ChildProcess::Outcome::line);
  CHECK(line == "kept new added");
  unsetenv("NUMLAB_TEST_KEPT");
  unsetenv("NUMLAB_TEST_REPLACED");
}
