// results.json (Exercism v3), the terminal text and report.html, from hand-made check results.

#include <catch2/catch.hpp>

#include "exercises/numbers.hpp"
#include "exercises/results.hpp"
#include "tiny_exercise.hpp"

using namespace numlab::exercises;
using Catch::Matchers::Contains;

namespace {

CheckResult passed(const std::string& name, int task_id = 1) {
  return {name, task_id, CheckStatus::pass, "", "", "", 0.00041, {{"numlab GEPP", 0.000012}, {"GSL LU", 0.000009}}, {}, "", std::nullopt};
}
CheckResult failed(const std::string& name, const std::string& message, const std::string& hint = "",
                   const std::string& output = "") {
  return {name, 2, CheckStatus::fail, message, hint, output, 0.0005, {{"GSL LU", 0.00001}}, {}, "", std::nullopt};
}
CheckResult errored(const std::string& name, const std::string& message) {
  return {name, 3, CheckStatus::error, message, "", "", 0.0, {}, {}, "", std::nullopt};
}

// 2 pass, 1 fails with a hint and stderr, 1 errors.
std::vector<CheckResult> mixed() {
  return {passed("solves a 3x3 system"), passed("solves a 50x50 system", 2),
          failed("pivots on the largest |a| in each column", "column 1: you pivoted on row 1 (|a| = 0.21)",
                 "no pivoting: you keep the diagonal entry", "debug: k = 1\n"),
          errored("says singular on a singular matrix", "the program exited (status 1) before replying")};
}

}  // namespace

TEST_CASE("results.json has the Exercism v3 shape: a mix of pass, fail and error is a fail", "[results]") {
  const auto json = results_json(mixed());
  CHECK(json["version"] == 3);
  CHECK(json["status"] == "fail");
  CHECK(json["message"].is_null());
  REQUIRE(json["tests"].size() == 4);
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  CHECK(keys == std::vector<std::string>{"version", "status", "message", "diagnosis", "diagnosis_cause", "variant", "tests"});
  CHECK(json["diagnosis"].is_null());  // no detector fired: the hint stays in its test
  CHECK(json["diagnosis_cause"].is_null());

  const auto& pass = json["tests"][0];
  CHECK(pass["name"] == "solves a 3x3 system");
  CHECK(pass["status"] == "pass");
  CHECK(pass["message"].is_null());
  CHECK(pass["task_id"].is_number_integer());
  CHECK(pass["task_id"] == 1);
  CHECK(pass["output"].is_null());
  CHECK(pass["timing"]["you"] == 0.00041);
  CHECK(pass["timing"]["numlab GEPP"] == 0.000012);
  CHECK(pass["timing"]["GSL LU"] == 0.000009);

  const auto& fail = json["tests"][2];
  CHECK(fail["status"] == "fail");
  CHECK(fail["task_id"] == 2);
  CHECK(fail["message"] == "column 1: you pivoted on row 1 (|a| = 0.21)\nHint: no pivoting: you keep the diagonal entry");
  CHECK(fail["output"] == "debug: k = 1\n");

  const auto& error = json["tests"][3];
  CHECK(error["status"] == "error");
  CHECK(error["message"] == "the program exited (status 1) before replying");
  CHECK(error["timing"]["you"].is_null());  // never timed: no reply
}

TEST_CASE("results.json: all pass is a pass, and every check errored is an error that says why", "[results]") {
  const auto pass = results_json({passed("a"), passed("b")});
  CHECK(pass["status"] == "pass");
  CHECK(pass["message"].is_null());

  const auto error = results_json({errored("a", "no reply within 10 s"), errored("b", "not run: ...")});
  CHECK(error["status"] == "error");
  REQUIRE(error["message"].is_string());
  CHECK_THAT(error["message"].get<std::string>(), Contains("'a'") && Contains("no reply within 10 s"));

  // A failing check among errors makes it a fail: the program did answer.
  CHECK(results_json({errored("a", "crash"), failed("b", "wrong")})["status"] == "fail");

  // The caller's reason wins, and no check at all is an error.
  const auto none = results_json({}, "the command cannot be started: nosuch");
  CHECK(none["status"] == "error");
  CHECK(none["message"] == "the command cannot be started: nosuch");
  CHECK(none["tests"].empty());
  CHECK(results_json({})["status"] == "error");
}

TEST_CASE("The text: one line per check with the times, the failures, the summary", "[results]") {
  const std::string text = results_text(numlab::test::tiny_exercise(), mixed());
  CHECK_THAT(text, Contains("✓ solves a 3x3 system\n    you 0.41 ms/request, numlab GEPP 0.012 ms, GSL LU 0.009 ms\n"));
  CHECK_THAT(text, Contains("✗ pivots on the largest |a| in each column\n    you 0.5 ms/request, GSL LU 0.01 ms\n"));
  CHECK_THAT(text, Contains("✗ says singular on a singular matrix (error)\n"));
  // The failures section: each non-passing check again, with its message, hint and output.
  const auto failures = text.find("Failures\n");
  REQUIRE(failures != std::string::npos);
  const std::string tail = text.substr(failures);
  CHECK_THAT(tail, Contains("✗ pivots on the largest |a| in each column\n"
                            "    column 1: you pivoted on row 1 (|a| = 0.21)\n"
                            "    Hint: no pivoting: you keep the diagonal entry\n"
                            "    Output (stderr):\n      | debug: k = 1\n"));
  CHECK_THAT(tail, Contains("the program exited (status 1) before replying"));
  CHECK(tail.find("solves a 3x3 system") == std::string::npos);
  CHECK(text.ends_with("\n2 of 4 checks pass; 1 fail, 1 error\n"));
}

TEST_CASE("The summary line counts each outcome, and long output is shortened in the text", "[results]") {
  CHECK(results_summary({passed("a"), passed("b")}) == "2 of 2 checks pass");
  CHECK(results_summary({errored("a", "x"), errored("b", "y")}) == "0 of 2 checks pass; 2 errors");
  CHECK(results_summary({failed("a", "x"), passed("b"), failed("c", "y")}) == "1 of 3 checks pass; 2 fail");
  std::string output;
  for (int line = 1; line <= 20; ++line) output += "line " + std::to_string(line) + "\n";
  const std::string text = results_text(numlab::test::tiny_exercise(), {failed("a", "wrong", "", output)});
  CHECK_THAT(text, Contains("| line 8\n") && Contains("(12 more lines)"));
  CHECK(text.find("line 9\n") == std::string::npos);
  // Without a failure there is no failures section.
  CHECK(results_text(numlab::test::tiny_exercise(), {passed("a")}).find("Failures") == std::string::npos);
}

TEST_CASE("report.html names every check, the command, the failures, and escapes <, > and &", "[results]") {
  auto results = mixed();
  results[2].message = "x <differs> from GSL & Eigen";
  results[2].output = "<script>alert(1)</script>";
  const std::string html = results_html(numlab::test::tiny_exercise(), results, "python3 a<b.py");
  CHECK(html.starts_with("<!DOCTYPE html>"));
  CHECK_THAT(html, Contains("<title>numlab exercise tiny-sum</title>"));
  for (const CheckResult& result : results) CHECK_THAT(html, Contains(result.name));
  CHECK_THAT(html, Contains("<code>python3 a&lt;b.py</code>"));
  CHECK_THAT(html, Contains("x &lt;differs&gt; from GSL &amp; Eigen"));
  CHECK_THAT(html, Contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
  CHECK(html.find("<script>") == std::string::npos);
  CHECK_THAT(html, Contains("Hint: no pivoting: you keep the diagonal entry"));
  CHECK_THAT(html, Contains("2 of 4 checks pass; 1 fail, 1 error"));
  // The times: the student's and one column per reference (ms), "-" where a check has none.
  CHECK_THAT(html, Contains("<th>you (ms/request)</th><th>numlab GEPP (ms)</th><th>GSL LU (ms)</th></tr>"));
  CHECK_THAT(html, Contains("<td>0.41</td><td>0.012</td><td>0.009</td></tr>"));
  CHECK_THAT(html, Contains("<td>0.5</td><td>-</td><td>0.01</td></tr>"));
}

TEST_CASE("The text and report.html lead with the first failure to fix, and give its replay", "[results]") {
  auto results = mixed();
  results[2].replay = "numlab exercise replay out/replay/03-pivots.jsonl -- python3 solution.py";
  const std::string text = results_text(numlab::test::tiny_exercise(), results);
  CHECK(text.starts_with("Fix first: pivots on the largest |a| in each column — column 1: you pivoted on row 1 "
                         "(|a| = 0.21)\nReplay it: numlab exercise replay out/replay/03-pivots.jsonl -- python3 "
                         "solution.py\n"));
  CHECK_THAT(text, Contains("    Replay: numlab exercise replay out/replay/03-pivots.jsonl -- python3 solution.py\n"));
  const std::string html = results_html(numlab::test::tiny_exercise(), results, "python3 solution.py");
  CHECK_THAT(html, Contains("<strong>Fix first:</strong> pivots on the largest |a| in each column — column 1"));
  CHECK(html.find("Fix first") < html.find("<h2>Checks</h2>"));
  CHECK_THAT(html, Contains("<p>Replay: <code>numlab exercise replay out/replay/03-pivots.jsonl -- python3 "
                            "solution.py</code></p>"));
  // All pass: nothing to fix first.
  CHECK(results_text(numlab::test::tiny_exercise(), {passed("a")}).find("Fix first") == std::string::npos);
  CHECK(results_html(numlab::test::tiny_exercise(), {passed("a")}, "x").find("Fix first") == std::string::npos);
}

TEST_CASE("A mismatched number shows 17 significant digits and the difference", "[results]") {
  // Two values equal to six digits, told apart.
  CHECK(compared(-43.351312345678901, -43.351298765432101) ==
        "-43.351312345678899, expected -43.351298765432098 (differs by 1.4e-05, 3.1e-07 relative)");
  CHECK(digits17(0.1) == "0.10000000000000001");
  CHECK(difference(0.5, 0.0) == "differs by 0.5");  // no relative difference from 0
  CHECK(difference(1.0, 1.0) == "differs by 0, 0 relative");
}

TEST_CASE("The most specific diagnosis leads the results and replaces its check's hint", "[results][diagnosis]") {
  std::vector<CheckResult> results = mixed();
  CheckResult family = failed("converges quadratically", "iteration 3: ratio 0.5", "check J");
  family.diagnosis = Diagnosis{"wrong_jacobian", Specificity::family, "J is not the derivative of f"};
  CheckResult exact = failed("sweeps like Gauss-Seidel", "sweep 1 differs", "a generic hint");
  exact.diagnosis = Diagnosis{"jacobi_sweep", Specificity::exact, "your sweep 1 equals a Jacobi sweep to 1e-16"};
  CheckResult later_exact = failed("another", "differs");
  later_exact.diagnosis = Diagnosis{"stop_test", Specificity::exact, "a later exact cause"};
  results.push_back(family);
  results.push_back(exact);
  results.push_back(later_exact);

  const auto json = results_json(results);
  CHECK(json["diagnosis_cause"] == "jacobi_sweep");  // exact beats family; the first exact wins
  CHECK(json["diagnosis"] == "your sweep 1 equals a Jacobi sweep to 1e-16");
  CHECK(json["tests"][5]["message"] == "sweep 1 differs\nDiagnosis: your sweep 1 equals a Jacobi sweep to 1e-16");
  CHECK(json["tests"][2]["message"] == "column 1: you pivoted on row 1 (|a| = 0.21)\nHint: no pivoting: you keep the diagonal entry");

  const Exercise exercise = numlab::test::tiny_exercise();
  const std::string text = results_text(exercise, results);
  CHECK(text.rfind("Diagnosis: your sweep 1 equals a Jacobi sweep to 1e-16\n", 0) == 0);
  CHECK_THAT(text, !Contains("a generic hint"));
  const std::string html = results_html(exercise, results, "python3 solution.py");
  CHECK(html.find("Diagnosis:</strong> your sweep 1 equals") < html.find("Fix first"));

  // A passing check's diagnosis is never reported: only failures are explained.
  std::vector<CheckResult> passing = {passed("a")};
  passing.front().diagnosis = exact.diagnosis;
  CHECK(results_json(passing)["diagnosis"].is_null());
}

TEST_CASE("diagnose keeps the most specific detector that fires, the first among equals", "[diagnosis]") {
  int calls = 0;
  const auto fires = [&](std::string evidence) {
    return [&calls, evidence] { ++calls; return std::optional<std::string>(evidence); };
  };
  const auto silent = [&] { ++calls; return std::optional<std::string>(); };
  CHECK_FALSE(diagnose({}).has_value());
  CHECK_FALSE(diagnose({{"a", Specificity::exact, silent}}).has_value());
  calls = 0;
  const auto d = diagnose({{"symptom", Specificity::symptom, fires("s")},
                           {"exact1", Specificity::exact, fires("e1")},
                           {"exact2", Specificity::exact, fires("e2")},
                           {"family", Specificity::family, fires("f")}});
  REQUIRE(d.has_value());
  CHECK(d->cause == "exact1");
  CHECK(d->evidence == "e1");
  CHECK(calls == 2);  // after an exact fired, the equal and lower ones were not tested
}
