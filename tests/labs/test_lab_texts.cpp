// Each lab's sentences against the numbers the same run printed: the tables are read back from
// the CSV files the lab saved, and every sentence made from them must name the same rows and
// ratios. No lab talks about developers' targets. Each test case runs its lab once.

#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <nlohmann/json.hpp>

#include "../cli/run_numlab.hpp"
#include "lab_checks.hpp"
#include "lab_output.hpp"

using Catch::Matchers::Contains;
using numlab::test::check_ratio;
using numlab::test::column;
using numlab::test::has_developer_talk;
using numlab::test::LabOutput;
using numlab::test::number;
using numlab::test::row_named;
using numlab::test::run_lab;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("numlab with no arguments shows measured ratios and why, no developer targets", "[labs][jansen]") {
  const LabOutput lab = run_lab("");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(has_developer_talk(lab.text));
  const auto rows = lab.table("step3-cycle-comparison.csv");
  const std::size_t time = column(rows, "time per cycle"), iterations = column(rows, "iterations");
  const auto& full = row_named(rows, "full");
  const auto& sequential = row_named(rows, "sequential");
  const auto& analytic = row_named(rows, "analytic");
  const auto& gsl = row_named(rows, "gsl-newton");
  // Which is faster and by how much, from the printed times.
  check_ratio(lab.text, "Sequential Newton is", number(sequential[time]), number(full[time]));
  check_ratio(lab.text, "Full Newton (hand-written GEPP) is", number(full[time]), number(gsl[time]));
  check_ratio(lab.text, "Full Newton is", number(full[time]), number(analytic[time]));
  // Why: the iterations it names are the table's.
  CHECK_THAT(lab.text, Contains(fmt::format("({} block iterations against {})", sequential[iterations],
                                            full[iterations])));
  CHECK_THAT(lab.text, Contains(fmt::format("({} for 360 poses)", full[iterations])));
}

TEST_CASE("Gauss lab: the Hilbert and Wilkinson sentences name the rows where the table changes", "[labs][gauss]") {
  const LabOutput lab = run_lab("gauss");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(has_developer_talk(lab.text));
  // 1. Hilbert: the first n whose kappa exceeds 1/eps, and the first n GEPP calls singular.
  const auto hilbert = lab.table("step4-hilbert.csv");
  const std::size_t kappa = column(hilbert, "kappa_1 estimate"), status = column(hilbert, "GEPP status");
  std::string exceeds, singular;
  for (std::size_t r = 1; r < hilbert.size(); ++r) {
    if (exceeds.empty() && number(hilbert[r][kappa]) * eps > 1.0) exceeds = hilbert[r][0];
    if (singular.empty() && hilbert[r][status] == "singular") singular = hilbert[r][0];
  }
  REQUIRE_FALSE(exceeds.empty());
  REQUIRE_FALSE(singular.empty());
  CHECK_THAT(lab.text, Contains("kappa first exceeds 1/eps = 4.5e+15 at n = " + exceeds + " "));
  CHECK_THAT(lab.text, Contains("GEPP first says 'singular' at n = " + singular + ":"));
  // 2. Wilkinson: the first n where GEPP keeps no digit.
  const auto wilkinson = lab.table("step3-wilkinson-growth.csv");
  const std::size_t digits = column(wilkinson, "GEPP digits");
  std::string lost;
  for (std::size_t r = 1; r < wilkinson.size() && lost.empty(); ++r) {
    if (wilkinson[r][digits] == "0.0") lost = wilkinson[r][0];
  }
  REQUIRE_FALSE(lost.empty());
  CHECK_THAT(lab.text, Contains("From n = " + lost + " "));
}

TEST_CASE("Gauss lab: the kept factors are Eigen's P, L and U, and the PA = LU sentence quotes the table", "[labs][gauss]") {
  const LabOutput lab = run_lab("gauss");
  REQUIRE(lab.exit_code == 0);
  // The lab's 3x3 system of step 1, factored independently.
  Eigen::MatrixXd A(3, 3);
  A << 2, 1, -1, -3, -1, 2, -2, 1, 2;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  const Eigen::MatrixXd L = lu.matrixLU().triangularView<Eigen::UnitLower>();
  const Eigen::MatrixXd U = lu.matrixLU().triangularView<Eigen::Upper>();
  const Eigen::MatrixXd PA = lu.permutationP() * A;
  const auto factors = lab.table("step1-factors.csv");
  REQUIRE(factors.size() == 4);
  const std::size_t row_of_a = column(factors, "row of A"), largest = column(factors, "max|PA - LU| in row");
  double max_difference = 0.0;
  for (int i = 0; i < 3; ++i) {
    const auto& row = factors[static_cast<std::size_t>(i) + 1];
    INFO("row " << i + 1);
    // Row i of P A is the row of A the table names.
    CHECK(A.row(static_cast<Eigen::Index>(number(row[row_of_a])) - 1) == PA.row(i));
    for (int j = 0; j < 3; ++j) {
      CHECK(number(row[column(factors, fmt::format("l_i{}", j + 1))]) == Approx(L(i, j)).margin(1e-6));
      CHECK(number(row[column(factors, fmt::format("u_i{}", j + 1))]) == Approx(U(i, j)).margin(1e-6));
    }
    max_difference = std::max(max_difference, number(row[largest]));
  }
  // The sentence's number is the table's largest |PA - LU| over max|a_ij| = 3, within rounding.
  CHECK(max_difference <= 3 * eps * 3.0);
  CHECK_THAT(lab.text, Contains(fmt::format("P A = L U to rounding: max|PA - LU| / max|a_ij| = {:.2g},",
                                            max_difference / 3.0)));
}

TEST_CASE("Mustang lab: where loop 3 stops is read from the row above it", "[labs][mustang]") {
  const LabOutput lab = run_lab("mustang");
  CHECK_FALSE(has_developer_talk(lab.text));
  const auto rows = lab.table("step2-seed-method.csv");
  const std::size_t loop3 = column(rows, "loop 3");
  std::vector<std::string> stops;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][loop3].ends_with(" its")) stops.push_back(rows[r][0] + " deg (after " + rows[r][loop3].substr(
                                                              0, rows[r][loop3].size() - 4) + " iterations");
  }
  const int total = static_cast<int>(rows.size()) - 1, failed = total - static_cast<int>(stops.size());
  if (stops.empty()) {
    CHECK_THAT(lab.text, Contains("it never stops on this grid"));
  } else {
    CHECK_THAT(lab.text, !Contains("never stops"));
    CHECK_THAT(lab.text, Contains(fmt::format("without stopping at {} of {} angles", failed, total)));
    for (const std::string& stop : stops) CHECK_THAT(lab.text, Contains(stop));
  }
}

TEST_CASE("inverse2x2 lab: digits lost are log10(forward error / eps) of the table's worst row", "[labs][inverse2x2]") {
  const LabOutput lab = run_lab("inverse2x2");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(has_developer_talk(lab.text));
  CHECK_THAT(lab.text, !Contains("every digit"));
  const auto rows = lab.table("step3-nearly-singular.csv");
  // The columns are: d, kappa_2, closed form, forward error, rel. residual, GSL LU, forward error, ...
  for (const auto& [method, error_column] : {std::pair{"The closed form", 3}, std::pair{"GSL LU", 6}}) {
    double worst = 0.0;
    std::string where;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const double error = number(rows[r][static_cast<std::size_t>(error_column)]);
      if (error > worst) worst = error, where = rows[r][0];
    }
    INFO(method << ": worst " << worst << " at d = " << where);
    REQUIRE(worst > eps);
    // The table prints 3 digits; the sentence's digits lost, to 0.1, must match within that rounding.
    const double lost = std::log10(worst / eps);
    const std::string sentence = fmt::format("{}'s worst forward error is {:.3g}, at d = {}: ", method, worst,
                                             number(where));
    CHECK_THAT(lab.text, Contains(sentence));
    const std::size_t at = lab.text.find(sentence);
    if (at != std::string::npos) CHECK(std::abs(number(lab.text.substr(at + sentence.size())) - lost) <= 0.051);
  }
}

TEST_CASE("Fit lab: legends only under marks, and numlab fit's condition numbers for the same matrix", "[labs][fit]") {
  const LabOutput lab = run_lab("fit");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(has_developer_talk(lab.text));
  // 1. A legend appears once if a table has its mark, and never otherwise.
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = lab.text.find(what); at != std::string::npos; at = lab.text.find(what, at + 1)) ++n;
    return n;
  };
  bool bang = false;
  for (const char* sweep : {"step5-degree-sweep-foot-path.csv", "step5-degree-sweep-wampler4.csv"}) {
    for (const auto& row : lab.table(sweep)) {
      for (const auto& cell : row) bang = bang || cell.ends_with(" !");
    }
  }
  CHECK(count("(! in the table") == (bang ? 1u : 0u));
  bool star = false;
  for (const auto& row : lab.table("step2-nist-lre.csv")) {
    for (const auto& cell : row) star = star || cell.ends_with(" *");
  }
  CHECK(count("(* = ") == (star ? 1u : 0u));
  // 2. The conditioning table and the NIST table show what numlab fit prints for Wampler4, degree 5.
  const auto conditions = lab.table("step3-scaling-conditions.csv");
  const auto nist = lab.table("step2-nist-lre.csv");
  const auto& wampler4 = row_named(nist, "Wampler4");
  const std::map<std::string, std::string> nist_column = {
      {"normal", "kappa normal"}, {"normal-scaled", "kappa scaled"}, {"gsl", "kappa gsl"}};
  for (const std::string method : {"normal", "normal-scaled", "gsl", "eigen-qr"}) {
    const nlohmann::json fit = numlab::test::run_json(
        "fit", "--data " + std::string(NUMLAB_NIST_DIR) + "/Wampler4.dat --degree 5 --method " + method, 0);
    const auto& row = row_named(conditions, method);
    INFO(method);
    CHECK(row.at(column(conditions, "kappa scaled")) == fmt::format("{:.3g}", fit["condition_estimate"].get<double>()));
    CHECK(row.at(column(conditions, "kappa as it stands")) ==
          fmt::format("{:.3g}", fit["condition_unscaled"].get<double>()));
    if (nist_column.contains(method)) {
      CHECK(wampler4.at(column(nist, nist_column.at(method))) ==
            fmt::format("{:.3g}", fit["condition_estimate"].get<double>()));
    }
  }
}

TEST_CASE("Seidel, newton, jansen-sequential and beest labs: no developer talk, sentences from the tables",
          "[labs]") {
  const LabOutput seidel = run_lab("seidel");
  CHECK(seidel.exit_code == 0);
  CHECK_FALSE(has_developer_talk(seidel.text));
  // The diverging count is the table's.
  const auto sweeps = seidel.table("step3-sweeps-vs-kappa.csv");
  const std::size_t plain = column(sweeps, "plain Gauss-Seidel");
  int diverged = 0;
  for (std::size_t r = 1; r < sweeps.size(); ++r) diverged += sweeps[r][plain].starts_with("diverged") ? 1 : 0;
  const int total = static_cast<int>(sweeps.size()) - 1;
  CHECK_THAT(seidel.text, Contains(diverged == total ? fmt::format("diverges on all {} of", total)
                                                     : fmt::format("diverges on {} of {}", diverged, total)));
  for (const std::string name : {"newton", "jansen-sequential", "beest"}) {
    const LabOutput lab = run_lab(name);
    INFO(name);
    CHECK(lab.exit_code == 0);
    CHECK_FALSE(has_developer_talk(lab.text));
  }
}
