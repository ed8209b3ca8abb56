// The student's trace beside numlab's (labs/exercises/trace_comparison.hpp, trace_page.hpp): the
// first parting step and its sentence, from the numbers, against an elimination done here; the
// comparison in results.json; the page (embedded traces, the parting row, self-contained).

#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "exercises/checker.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/function_session.hpp"
#include "exercises/results.hpp"
#include "exercises/trace_page.hpp"
#include "gepp_solution.hpp"

namespace {

using numlab::exercises::CheckResult;
using numlab::exercises::CheckStatus;
using numlab::exercises::FunctionSession;
using numlab::exercises::TraceComparison;

std::vector<CheckResult> run_gepp(gepp_solution::PivotRule rule) {
  FunctionSession session("gepp", [rule](const nlohmann::json& request) {
    nlohmann::json reply = gepp_solution::solve_with(request, rule);
    reply["id"] = request["id"];
    return reply;
  });
  return numlab::exercises::run_checks(numlab::exercises::gepp_exercise(), session);
}

// The column where a pivot rule first picks another row than the largest |a_ik|, eliminating as
// the rule does (both agree up to there), with the two rows and their |a|: done here, not by numlab.
struct Parting {
  std::size_t column = 0;
  std::size_t yours = 0, numlab = 0;
  double your_size = 0.0, numlab_size = 0.0;
};

Parting first_parting(nlohmann::json A, gepp_solution::PivotRule rule) {
  std::vector<std::vector<double>> a = A.get<std::vector<std::vector<double>>>();
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t largest = k, chosen = k;
    for (std::size_t i = k + 1; i < n; ++i) {
      if (std::abs(a[i][k]) > std::abs(a[largest][k])) largest = i;
      if (rule == gepp_solution::PivotRule::largest_signed_value && a[i][k] > a[chosen][k]) chosen = i;
    }
    if (largest != chosen) return {k, chosen, largest, std::abs(a[chosen][k]), std::abs(a[largest][k])};
    std::swap(a[k], a[chosen]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const double l = a[i][k] / a[k][k];
      for (std::size_t j = k; j < n; ++j) a[i][j] -= l * a[k][j];
    }
  }
  FAIL("the rule never parts from partial pivoting on this matrix");
  return {};
}

const CheckResult& trace_check(const std::vector<CheckResult>& results) {
  const CheckResult* found = numlab::exercises::failing_trace_check(results);
  REQUIRE(found != nullptr);
  return *found;
}

// The JSON between <script type="application/json" id="trace-data"> and </script>.
nlohmann::json embedded_data(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"trace-data\">";
  const std::size_t start = page.find(open);
  REQUIRE(start != std::string::npos);
  const std::size_t end = page.find("</script>", start);
  return nlohmann::json::parse(page.substr(start + open.size(), end - start - open.size()));
}

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

}  // namespace

TEST_CASE("told_apart gives the fewest digits (at least 3) that tell two numbers apart") {
  CHECK(numlab::exercises::told_apart(7.0, 3.0) == std::pair<std::string, std::string>{"7", "3"});
  CHECK(numlab::exercises::told_apart(0.123456, 0.123451) == std::pair<std::string, std::string>{"0.12346", "0.12345"});
  CHECK(numlab::exercises::told_apart(1.0, 1.0 + 2.2e-16) ==
        std::pair<std::string, std::string>{"1", "1.0000000000000002"});
  CHECK(numlab::exercises::told_apart(2.5, 2.5) == std::pair<std::string, std::string>{"2.5", "2.5"});
}

TEST_CASE("GEPP without pivoting: the comparison parts at the first column where the largest |a| is not the diagonal") {
  const auto results = run_gepp(gepp_solution::PivotRule::none);
  const CheckResult& check = trace_check(results);
  REQUIRE(check.name.find("(trace)") != std::string::npos);
  const TraceComparison& comparison = *check.trace;
  const nlohmann::json& request = check.exchanges.back().request;
  const Parting parting = first_parting(request["A"], gepp_solution::PivotRule::none);
  CHECK(comparison.parting == parting.column);
  CHECK(comparison.parting_field == "pivot_row");
  const auto [numlab_size, your_size] = numlab::exercises::told_apart(parting.numlab_size, parting.your_size);
  CHECK(comparison.sentence == fmt::format("step {} (column {}): you took row {} as the pivot, numlab row {} (|a| = {} > {})",
                                           parting.column + 1, parting.column, parting.yours, parting.numlab, numlab_size,
                                           your_size));
  // Both traces as sent and as numlab's stepper made them: every column of each.
  const std::size_t n = request["A"].size();
  REQUIRE(comparison.yours.size() == check.exchanges.back().reply["trace"].size());
  for (std::size_t k = 0; k < comparison.yours.size(); ++k) {
    CHECK(comparison.yours[k]["pivot_row"] == check.exchanges.back().reply["trace"][k]["pivot_row"]);
    CHECK(comparison.yours[k]["pivot"] == check.exchanges.back().reply["trace"][k]["pivot"]);
  }
  REQUIRE(comparison.numlab.size() == n);
  const nlohmann::json& expected = check.exchanges.back().expected.reply["trace"];
  for (std::size_t k = 0; k < n; ++k) {
    CHECK(comparison.numlab[k]["pivot_row"] == expected[k]["pivot_row"]);
    CHECK(comparison.numlab[k]["pivot"] == expected[k]["pivot"]);
    CHECK(comparison.context[k]["candidates"].size() == n - k);
  }
  // Column 0's candidates are A's first column.
  for (std::size_t i = 0; i < n; ++i) CHECK(comparison.context[0]["candidates"][i] == request["A"][i][0]);
}

TEST_CASE("GEPP pivoting on the signed value: the comparison parts where the signed and the absolute largest differ") {
  const auto results = run_gepp(gepp_solution::PivotRule::largest_signed_value);
  const CheckResult& check = trace_check(results);
  const Parting parting = first_parting(check.exchanges.back().request["A"], gepp_solution::PivotRule::largest_signed_value);
  CHECK(check.trace->parting == parting.column);
  CHECK(check.trace->sentence.starts_with(fmt::format("step {} (column {}): you took row {} as the pivot, numlab row {} (",
                                                      parting.column + 1, parting.column, parting.yours, parting.numlab)));
}

TEST_CASE("A correct GEPP has no trace comparison and no page") {
  const auto results = run_gepp(gepp_solution::PivotRule::largest_magnitude);
  for (const CheckResult& result : results) CHECK_FALSE(result.trace.has_value());
  CHECK(numlab::exercises::failing_trace_check(results) == nullptr);
  const auto json = numlab::exercises::results_json(results);
  for (const auto& test : json["tests"]) CHECK_FALSE(test.contains("trace"));
  CHECK(numlab::exercises::results_html(numlab::exercises::gepp_exercise(), results, "solution").find("trace.html") ==
        std::string::npos);
}

TEST_CASE("results.json carries the comparison, the page embeds the same numbers and marks the parting row") {
  const auto results = run_gepp(gepp_solution::PivotRule::none);
  const CheckResult& check = trace_check(results);
  const auto json = numlab::exercises::results_json(results);
  std::size_t with_trace = 0;
  nlohmann::json traced;
  for (const auto& test : json["tests"]) {
    if (test.contains("trace")) {
      ++with_trace;
      traced = test;
    }
  }
  REQUIRE(with_trace == 1);
  CHECK(traced["name"] == check.name);
  const std::string page = numlab::exercises::trace_page_html(numlab::exercises::gepp_exercise(), check);
  nlohmann::json data = embedded_data(page);
  CHECK(data["check"] == check.name);
  data.erase("check");
  CHECK(data == nlohmann::json::parse(traced["trace"].dump()));
  // The static view: one row per column, the parting one marked once, the sentence at the top.
  const std::size_t parting = check.trace->parting;
  CHECK(occurrences(page, "class=\"parting\"") == 1);
  CHECK(page.find(fmt::format("<tr id=\"step-{}\" class=\"parting\">", parting + 1)) != std::string::npos);
  CHECK(occurrences(page, "<tr id=\"step-") == std::max(check.trace->yours.size(), check.trace->numlab.size()));
  CHECK(page.find(check.trace->sentence) != std::string::npos);
  // The stepper is hidden until its script shows it; nothing is loaded from elsewhere.
  CHECK(page.find("<section id=\"stepper\" aria-label=\"Step through both traces\" hidden>") != std::string::npos);
  CHECK(page.find(" src=") == std::string::npos);
  CHECK(page.find("href=\"http") == std::string::npos);
  CHECK(page.find("url(") == std::string::npos);
  CHECK(page.find("@import") == std::string::npos);
  CHECK(page.ends_with("</html>\n"));
  // report.html links to it and names the parting step.
  const std::string report = numlab::exercises::results_html(numlab::exercises::gepp_exercise(), results, "solution");
  CHECK(report.find(fmt::format("<a href=\"trace.html\">trace.html</a> (step {} (column {}): you took row", parting + 1,
                                parting)) != std::string::npos);
}

TEST_CASE("The embedded traces cannot end the script they are in") {
  CheckResult result;
  result.name = "a check </script><script>alert(1)</script>";
  result.status = CheckStatus::fail;
  TraceComparison comparison = numlab::exercises::newton_comparison("crank </script> 30 deg", {1.0}, {0.5}, {1.0, 1e-3},
                                                                    {0.5, 0.2}, 1, {1e-6, 1e-12, 1e-12, 1e-10});
  result.trace = comparison;
  const std::string page = numlab::exercises::trace_page_html(numlab::exercises::gepp_exercise(), result);
  CHECK(occurrences(page, "</script>") == 2);  // the data's and the script's own
  CHECK(embedded_data(page)["inputs"] == "crank </script> 30 deg");
}

TEST_CASE("Gauss-Seidel sweeps: the sentence names the entry of x that parts most, with both values") {
  const std::vector<Eigen::VectorXd> xs = {(Eigen::VectorXd(3) << 0.5, 0.25, 0.125).finished(),
                                           (Eigen::VectorXd(3) << 0.75, 0.5, 0.3).finished()};
  const std::vector<double> updates = {0.5, 0.25};
  nlohmann::json trace = {{{"x", {0.5, 0.25, 0.125}}, {"update_inf", 0.5}},
                          {{"x", {0.75, 0.625, 0.3}}, {"update_inf", 0.375}}};
  const TraceComparison comparison = numlab::exercises::sweep_comparison("a 3x3", trace, xs, updates, 1, 1e-12);
  CHECK(comparison.parting_field == "x");
  CHECK(comparison.parting_entry == 1);
  CHECK(comparison.sentence == "step 2 (sweep 2): your x[1] = 0.625 where numlab's is 0.5 (they differ by 0.12, allowed 1e-12)");
  // A trace that ends early parts where it ends.
  trace.erase(1);
  CHECK(numlab::exercises::sweep_comparison("a 3x3", trace, xs, updates, 1, 1e-12).sentence ==
        "step 2 (sweep 2): your trace ends after 1 sweeps; numlab's goes on to sweep 2 (update_inf 0.25 after sweep 2)");
}

TEST_CASE("Newton: the sentence says which of ||f|| and ||dx|| parts, with both values") {
  const numlab::exercises::NewtonTolerances tolerances{1e-6, 1e-12, 1e-12, 1e-10};
  const auto residual_only = numlab::exercises::newton_comparison("crank 30 deg", {4.0, 9.5}, {1.0, 0.5}, {4.0, 0.02},
                                                                  {1.0, 0.5}, 1, tolerances);
  CHECK(residual_only.sentence == "step 2 (iteration 2): your ||f||_inf = 9.5 where numlab's is 0.02 (your ||dx||_inf = 0.5 is numlab's)");
  CHECK(residual_only.parting_field == "residual_inf");
  const auto longer = numlab::exercises::newton_comparison("crank 30 deg", {4.0, 1e-3, 1e-14}, {1.0, 0.5, 1e-3},
                                                           {4.0, 1e-3}, {1.0, 0.5}, 2, tolerances);
  CHECK(longer.sentence == "step 3 (iteration 3): your trace goes on to iteration 3; numlab's Newton stops after 2 (||f||_inf = 0.001)");
}

TEST_CASE("A long trace keeps its first 2000 steps (and the parting step beyond them), and the page says so") {
  const numlab::exercises::NewtonTolerances tolerances{1e-6, 1e-12, 1e-12, 1e-10};
  std::vector<double> residuals(2500), steps(2500);
  for (std::size_t k = 0; k < residuals.size(); ++k) {
    residuals[k] = 1.0 / static_cast<double>(k + 1);
    steps[k] = 0.5;
  }
  std::vector<double> yours = residuals;
  yours[2200] *= 2.0;  // parts at iteration 2201
  const TraceComparison comparison =
      numlab::exercises::newton_comparison("a long run", yours, steps, residuals, steps, 2200, tolerances);
  CHECK(comparison.yours.size() == 2201);
  CHECK(comparison.numlab.size() == 2201);
  CHECK(comparison.yours_total == 2500);
  CHECK(comparison.yours[2200]["residual_inf"] == yours[2200]);
  const TraceComparison early =
      numlab::exercises::newton_comparison("a long run", yours, steps, residuals, steps, 10, tolerances);
  CHECK(early.yours.size() == numlab::exercises::kept_trace_steps);
  CheckResult result;
  result.name = "a long trace";
  result.status = CheckStatus::fail;
  result.trace = early;
  const std::string page = numlab::exercises::trace_page_html(numlab::exercises::gepp_exercise(), result);
  CHECK(page.find("Your trace has 2500 iterations; the first 2000 are shown.") != std::string::npos);
  CHECK(page.find("numlab's has 2500 iterations; the first 2000 are shown.") != std::string::npos);
  CHECK(occurrences(page, "<tr id=\"step-") == 2000);
}
