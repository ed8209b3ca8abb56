// Lab robustness: every sentence against the tables the same run saved. No case count, case name
// or solver count is written here: they all come from the lab's own tables, so the test holds as
// the MINPACK case list grows.

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "../labs/lab_output.hpp"
#include "lessons/lab_sentences.hpp"

using numlab::cli::count_of;
using numlab::test::column;
using numlab::test::CsvRows;
using numlab::test::LabOutput;
using numlab::test::number;

namespace {

// Solver name -> solved count, from the lab's first table; `cases` gets the case count.
std::map<std::string, int> solved_counts(const LabOutput& lab, int& cases) {
  const CsvRows rows = lab.table("step1-counts.csv");
  std::map<std::string, int> solved;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    solved[rows[r][0]] = static_cast<int>(number(rows[r][column(rows, "solved")]));
    cases = static_cast<int>(number(rows[r][column(rows, "cases")]));
    CHECK(number(rows[r][column(rows, "solved")]) <= number(rows[r][column(rows, "applies to")]));
    CHECK(number(rows[r][column(rows, "applies to")]) <= cases);
  }
  return solved;
}

// "case: status (||f||_inf = r)" for each row of a failure table, in order, joined by "; ".
std::string failure_list(const CsvRows& rows) {
  if (rows.size() < 2) return "none";
  std::string list;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    list += fmt::format("{}{}: {} (||f||_inf = {})", r > 1 ? "; " : "", rows[r][0], rows[r][column(rows, "status")],
                        rows[r][column(rows, "||f||_inf")]);
  }
  return list;
}

// Rows of a two-solver difference table where the first column's solver solved and the second did not.
int solved_by_column(const CsvRows& rows, std::size_t solved_column) {
  int count = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) count += rows[r][solved_column] == "solved" ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("robustness lab: every count and every failure named comes from its tables", "[labs][robustness][lab-text-release-only]") {
  const LabOutput lab = numlab::test::run_lab("robustness");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(numlab::test::has_developer_talk(lab.text));
  int cases = 0;
  const auto solved = solved_counts(lab, cases);
  REQUIRE(cases > 0);
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("{} cases from", cases)));
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("; {} solvers.", solved.size())));

  // Step 2: plain Newton's failures, one row each, all named with their status.
  const CsvRows plain = lab.table("step2-plain-failures.csv");
  CHECK(static_cast<int>(plain.size()) - 1 == cases - solved.at("newton-gepp"));
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("newton-gepp solves {} cases. It fails on {}: {}.",
                                                   count_of(solved.at("newton-gepp"), cases), plain.size() - 1,
                                                   failure_list(plain))));

  // Step 3: what damping rescues and loses, from the rows where the two differ.
  const CsvRows damping = lab.table("step3-damping.csv");
  const int lost = solved_by_column(damping, 1);
  const int rescued = solved_by_column(damping, 2);
  CHECK(solved.at("damped-gepp") - solved.at("newton-gepp") == rescued - lost);
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("damped-gepp solves {} cases, newton-gepp {}. Damping rescues {} case(s)",
                                                   count_of(solved.at("damped-gepp"), cases),
                                                   count_of(solved.at("newton-gepp"), cases), rescued)));
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("and loses {} case(s) plain Newton solves", lost)));

  // Step 4: the best dogleg and newton-like types are the ones with the most cases in the table.
  const CsvRows types = lab.table("step4-gsl-types.csv");
  std::map<std::string, std::pair<std::string, int>> best;  // family -> (type, solved)
  for (std::size_t r = 1; r < types.size(); ++r) {
    const int count = static_cast<int>(number(types[r][column(types, "solved")]));
    CHECK(count == solved.at(types[r][0]));
    auto& [type, most] = best[types[r][column(types, "family")]];
    if (type.empty() || count > most) type = types[r][0], most = count;
  }
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("The best dogleg type, {}, solves {} cases; the best newton-like type, "
                                                   "{}, solves {}.", best["dogleg"].first,
                                                   count_of(best["dogleg"].second, cases), best["newton-like"].first,
                                                   count_of(best["newton-like"].second, cases))));
  const CsvRows dogleg = lab.table("step4-dogleg-vs-damped.csv");
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("{} solves {} case(s) damped-gepp fails", best["dogleg"].first,
                                                   solved_by_column(dogleg, 2))));
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("damped-gepp solves {} case(s) {} fails.", solved_by_column(dogleg, 1),
                                                   best["dogleg"].first)));

  const CsvRows cost = lab.table("step4-dogleg-cost.csv");
  if (cost.size() > 1) {
    std::vector<double> damped, hybrid;
    for (std::size_t r = 1; r < cost.size(); ++r) {
      damped.push_back(number(cost[r][1]));
      hybrid.push_back(number(cost[r][2]));
    }
    // The upper median, computed here by sorting.
    std::sort(damped.begin(), damped.end());
    std::sort(hybrid.begin(), hybrid.end());
    CHECK_THAT(lab.text, Catch::Contains(fmt::format("On the {} cases both solve, {} needs a median of {:g} function "
                                                     "evaluations (a Jacobian counted as n) and damped-gepp {:g}.",
                                                     cost.size() - 1, best["dogleg"].first, hybrid[hybrid.size() / 2],
                                                     damped[damped.size() / 2])));
  }

  // Step 5: yes or no from the counts; a no lists every case of the table of why.
  int best_damped = 0, best_gsl = 0;
  for (const auto& [solver, count] : solved) {
    if (solver.starts_with("damped-") && !solver.ends_with("inverse2x2")) best_damped = std::max(best_damped, count);
    if (solver.starts_with("gsl-")) best_gsl = std::max(best_gsl, count);
  }
  if (best_damped >= best_gsl) {
    CHECK_THAT(lab.text, Catch::Contains("Yes: "));
  } else {
    const CsvRows why = lab.table("step5-best-gsl-why.csv");
    CHECK(static_cast<int>(why.size()) - 1 >= best_gsl - best_damped);
    CHECK_THAT(lab.text, Catch::Contains(fmt::format("cases, GSL's best type")));
    CHECK_THAT(lab.text, Catch::Contains("with the status damped Newton stopped with: " + failure_list(why) + "."));
  }
  CHECK_THAT(lab.text, Catch::Contains(fmt::format("(dogleg, numlab/nonlinear/dogleg.hpp) solves {} cases, {}",
                                                   count_of(solved.at("dogleg"), cases),
                                                   solved.at("dogleg") >= best_gsl ? "at least as many as" : "fewer than")));
}
