// Lab `linkage`: every sentence against the tables the same run saved (read back from its CSV
// files), and the sentence builders of labs/lessons/linkage_sentences.hpp on cases the lab's own
// run does not reach (a Newton block, a limit that is not a fold, a slower block solve).

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

#include "lab_checks.hpp"
#include "lab_output.hpp"
#include "lessons/linkage_sentences.hpp"

using Catch::Matchers::Contains;
using numlab::test::column;
using numlab::test::check_ratio;
using numlab::test::CsvRows;
using numlab::test::has_developer_talk;
using numlab::test::LabOutput;
using numlab::test::number;
using numlab::test::row_named;
using numlab::test::run_lab;
using namespace numlab::cli;

namespace {

// The number printed right after `before` in the text (the first occurrence).
double number_after(const std::string& text, const std::string& before) {
  const std::size_t at = text.find(before);
  INFO("looking for: " << before);
  REQUIRE(at != std::string::npos);
  return number(text.substr(at + before.size(), 24));
}

// A number the sentence prints with `digits` significant digits (fmt's {:.Ng}) against the same
// number the table prints with 3 (scientific(), {:.3g}): both are roundings of one double, so they
// differ by at most half a unit of each one's last digit.
void check_rounded(double in_sentence, double in_table, int digits) {
  const double sentence_unit = std::pow(10.0, std::floor(std::log10(std::abs(in_table))) - (digits - 1));
  const double table_unit = std::pow(10.0, std::floor(std::log10(std::abs(in_table))) - 2);
  CHECK(std::abs(in_sentence - in_table) <= 0.5 * sentence_unit + 0.5 * table_unit + 1e-12 * std::abs(in_table));
}

// "12 of 144" -> 12.
int nonzeros(const std::string& cell) { return static_cast<int>(number(cell)); }

}  // namespace

TEST_CASE("Linkage lab: every sentence is made from the tables the same run saved", "[labs][linkage]") {
  const LabOutput lab = run_lab("linkage");
  REQUIRE(lab.exit_code == 0);
  CHECK_FALSE(has_developer_talk(lab.text));
  const std::string& text = lab.text;

  {  // step 1: unknowns, equations, mobility and blocks as the tables list them
    const auto model = lab.table("step1-model.csv");
    const auto blocks = lab.table("step1-blocks.csv");
    const auto& counts = model.at(1);
    const int moving = std::stoi(counts[column(model, "moving joints")]);
    CHECK(std::stoi(counts[column(model, "unknowns")]) == 2 * moving);  // x and y of each moving joint
    // Every moving joint is solved by exactly one block.
    CHECK(static_cast<int>(blocks.size()) - 1 == moving);
    int dyads = 0, explicit_blocks = 0;
    for (std::size_t r = 1; r < blocks.size(); ++r) {
      const std::string& kind = blocks[r][column(blocks, "kind")];
      dyads += kind.starts_with("dyad") ? 1 : 0;
      explicit_blocks += kind.ends_with("explicit") ? 1 : 0;
    }
    CHECK_THAT(text, Contains(fmt::format("{}'s {} moving joints give {} unknowns (the x and y of each) and {} equations; "
                                          "the mobility is {}",
                                          counts[0], moving, counts[column(model, "unknowns")],
                                          counts[column(model, "equations")], counts[column(model, "mobility")])));
    CHECK_THAT(text, Contains(fmt::format("Of its {} blocks, {} are dyads in closed form and {} are explicit;",
                                          blocks.size() - 1, dyads, explicit_blocks)));
    if (dyads + explicit_blocks == static_cast<int>(blocks.size()) - 1) CHECK_THAT(text, Contains("none needs Newton"));
  }

  {  // step 2: the ratios and iterations of the cycle table
    const auto rows = lab.table("step2-cycle-comparison.csv");
    const std::size_t time = column(rows, "time per cycle"), iterations = column(rows, "iterations");
    const auto& full = row_named(rows, "full");
    const auto& sequential = row_named(rows, "sequential");
    const auto& analytic = row_named(rows, "analytic");
    const auto& gsl = row_named(rows, "gsl-newton");
    check_ratio(text, "Sequential Newton is", number(sequential[time]), number(full[time]));
    check_ratio(text, "Full Newton (hand-written GEPP) is", number(full[time]), number(gsl[time]));
    check_ratio(text, "Full Newton is", number(full[time]), number(analytic[time]));
    CHECK_THAT(text, Contains(fmt::format("({} block iterations against {})", sequential[iterations], full[iterations])));
    CHECK_THAT(text, Contains(fmt::format("({} for 360 poses)", full[iterations])));
    // The iterations ratio and the cost of one iteration, from the printed times and counts.
    const double more = number(sequential[iterations]) / number(full[iterations]);
    CHECK(std::abs(number_after(text, "It takes ") - more) <= 0.051);
    const double per_sequential = number(sequential[time]) / number(sequential[iterations]);
    const double per_full = number(full[time]) / number(full[iterations]);
    const double cheaper = std::max(per_full / per_sequential, per_sequential / per_full);
    const std::string direction = per_sequential < per_full ? "less." : "more.";
    const std::size_t at = text.find("and each costs ");
    REQUIRE(at != std::string::npos);
    CHECK(std::abs(number(text.substr(at + 15)) - cheaper) <= 0.05 + cheaper * 0.011);
    CHECK(text.substr(at, 40).find(direction) != std::string::npos);
    // The worst distance it names is the table's largest.
    double worst = 0.0;
    for (std::size_t r = 1; r < rows.size(); ++r) worst = std::max(worst, number(rows[r][column(rows, "distance from seed 000")]));
    check_rounded(number_after(text, "closed form is at most "), worst, 2);
  }

  {  // step 3: the derivative differences and speeds of the table
    const auto rows = lab.table("step3-derivatives.csv");
    double velocity = 0.0, acceleration = 0.0, slowest = INFINITY, fastest = 0.0;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      velocity = std::max(velocity, number(rows[r][column(rows, "velocity vs central difference")]));
      acceleration = std::max(acceleration, number(rows[r][column(rows, "acceleration vs 7-point stencil")]));
      const double speed = number(rows[r][column(rows, "|v_F| (per rad)")]);
      slowest = std::min(slowest, speed), fastest = std::max(fastest, speed);
      // The speed from the file's model and from seed 000's hand-written rates, printed to 1e-6.
      CHECK(std::abs(speed - number(rows[r][column(rows, "seed 000's |v_F|")])) <= 1.01e-6);
    }
    CHECK_THAT(text, Contains(fmt::format("At these {} poses", rows.size() - 1)));
    check_rounded(number_after(text, "central differences of solved positions by at most "), velocity, 2);
    check_rounded(number_after(text, "7-point stencil by at most "), acceleration, 2);
    CHECK_THAT(text, Contains(fmt::format("speed ranges from {:.2f} to {:.2f} per radian", slowest, fastest)));
  }

  {  // step 4: the limit, the trends and the exponents of the table
    const auto rows = lab.table("step4-limit-approach.csv");
    const std::string mu_header = rows.at(0).at(2);  // "mu_P10 (deg)": the dyad's joint
    const std::string joint = mu_header.substr(3, mu_header.find(' ') - 3);
    const std::size_t before = column(rows, "before the limit (deg)"), kappa = column(rows, "kappa(J)");
    const std::size_t mu = column(rows, mu_header), speed = column(rows, "|v_" + joint + "| (per rad)");
    // The limit is the crank of the row 0 deg before it; the block named is the dyad of that joint.
    const auto& at_limit = row_named(rows, "0");
    CHECK_THAT(text, Contains(fmt::format("puts the limit at {:.2f} deg", number(at_limit[column(rows, "crank (deg)")]))));
    CHECK_THAT(text, Contains("(" + joint + " from ("));
    // The trends, recomputed from the printed columns.
    std::vector<double> mus, kappas;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      mus.push_back(number(rows[r][mu]));
      kappas.push_back(number(rows[r][kappa]));
    }
    CHECK_THAT(text, Contains(fmt::format("transmission angle {} deg, and kappa(J) {}.", trend_phrase(mus), trend_phrase(kappas))));
    // The exponents between 1 and 0.1 deg before the limit, from the printed values (3 or 4 digits
    // each: an exponent over one decade is then good to about 0.005, the sentence prints 0.01).
    const auto& far = row_named(rows, "1");
    const auto& near = row_named(rows, "0.1");
    REQUIRE(number(far[before]) == 1.0);
    const double p_kappa = measured_exponent(1.0, number(far[kappa]), 0.1, number(near[kappa]));
    const double p_speed = measured_exponent(1.0, number(far[speed]), 0.1, number(near[speed]));
    const double p_mu = measured_exponent(1.0, number(far[mu]), 0.1, number(near[mu]));
    CHECK(std::abs(number_after(text, "kappa(J) grows like d^") - p_kappa) <= 0.015);
    CHECK(std::abs(number_after(text, "speed like d^") - p_speed) <= 0.015);
    CHECK(std::abs(number_after(text, "transmission angle falls like d^") - p_mu) <= 0.015);
    const bool fold = std::abs(p_kappa + 0.5) <= 0.09 && std::abs(p_speed + 0.5) <= 0.09 && std::abs(p_mu - 0.5) <= 0.09;
    const bool not_fold = std::abs(p_kappa + 0.5) > 0.11 || std::abs(p_speed + 0.5) > 0.11 || std::abs(p_mu - 0.5) > 0.11;
    if (fold) CHECK_THAT(text, Contains("within 0.1 of the square-root law of a fold"));
    if (not_fold) CHECK_THAT(text, Contains("not the square-root law of a simple fold"));
  }

  {  // step 5: the crossing, its kappa and the tangents either side, each from its row
    const auto rows = lab.table("step5-crossing.csv");
    REQUIRE(rows.size() == 12);  // -10 to 10 deg by 2, and the header
    const auto& before = rows[5];  // -2 deg
    const auto& at = rows[6];      // 0 deg: on the crossing
    const auto& after = rows[7];   // 2 deg
    REQUIRE(at[0] == "0");
    CHECK(at[column(rows, "side")] == "on the crossing");
    CHECK(before[column(rows, "side")] != after[column(rows, "side")]);  // the smooth branch changes side
    const std::size_t kappa = column(rows, "kappa(J)"), v = column(rows, "v_B (per rad)"), w = column(rows, "other branch v_B");
    CHECK(number(at[kappa]) > 1e3 * number(rows[1][kappa]));  // J (nearly) singular on the crossing
    check_rounded(number_after(text, "cross: kappa(J) is "), number(at[kappa]), 3);
    CHECK_THAT(text, Contains(fmt::format("2 deg before it B moves at {} per radian of crank", before[v])));
    CHECK_THAT(text, Contains(fmt::format("2 deg after it at {} on the branch the sweep followed", after[v])));
    CHECK_THAT(text, Contains(fmt::format("and at {} on the other", after[w])));
    CHECK_THAT(text, Contains(fmt::format("from {} to {}", before[column(rows, "side")], after[column(rows, "side")])));
    // The turns the sentence names, from the printed tangents: small on the smooth branch, large to the other.
    const auto pair = [](const std::string& cell) {
      const std::size_t comma = cell.find(',');
      return std::pair{number(cell.substr(1, comma - 1)), number(cell.substr(comma + 1))};
    };
    const auto turn = [&](const std::string& a, const std::string& b) {
      const auto [ax, ay] = pair(a);
      const auto [bx, by] = pair(b);
      return std::acos((ax * bx + ay * by) / (std::hypot(ax, ay) * std::hypot(bx, by))) * 180.0 / std::acos(-1.0);
    };
    const double smooth_turn = number_after(text, "on the branch the sweep followed (");
    const double other_turn = number_after(text, "on the other (");
    CHECK(std::abs(smooth_turn - turn(before[v], after[v])) < 0.1);
    CHECK(std::abs(other_turn - turn(before[v], after[w])) < 0.1);
    CHECK(smooth_turn < 10.0);
    CHECK(other_turn > 90.0);
  }

  {  // step 7: the three models' sizes, times and distances
    const auto rows = lab.table("step7-over-modelling.csv");
    REQUIRE(rows.size() == 4);
    const auto &ten = rows[1], &eight = rows[2], &derived = rows[3];
    const std::size_t time = column(rows, "time per cycle"), unknowns = column(rows, "unknowns");
    const std::size_t entries = column(rows, "Jacobian nonzeros"), iterations = column(rows, "iterations");
    check_ratio(text, "its full Newton is", number(ten[time]), number(eight[time]));
    check_ratio(text, "all the same, about (12/8)^3 = 3.4 times the operations of the 8x8 LU, and is",
                number(derived[time]), number(eight[time]));
    CHECK(derived[unknowns] == lab.table("step1-model.csv").at(1).at(2));  // step 1's unknowns
    CHECK_THAT(text, Contains(fmt::format("only {} of its {} Jacobian entries are nonzero", nonzeros(derived[entries]),
                                          number(derived[unknowns]) * number(derived[unknowns]))));
    const auto share = [&](const std::vector<std::string>& row) {
      return 100.0 * nonzeros(row[entries]) / (number(row[unknowns]) * number(row[unknowns]));
    };
    CHECK_THAT(text, Contains(fmt::format("({:.0f}%, against {:.0f}% for seed 000's 8x8 and {:.0f}% for seed 001's 10x10)",
                                          share(derived), share(eight), share(ten))));
    CHECK_THAT(text, Contains(fmt::format("{} iterations against {})", derived[iterations], eight[iterations])));
    // The derived J's nonzeros are within the pattern --explain printed in step 1 (an 'x' marks
    // both unknowns of a joint the row reads, so the pattern can only hold more).
    const std::regex pattern_row(R"( \d+ ([x.]{12}) )");
    int marked = 0, pattern_rows = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern_row); it != std::sregex_iterator(); ++it) {
      const std::string cells = (*it)[1];
      marked += static_cast<int>(std::count(cells.begin(), cells.end(), 'x'));
      ++pattern_rows;
    }
    CHECK(pattern_rows == 12);
    CHECK(nonzeros(derived[entries]) <= marked);
    // The distances named, each from its row.
    check_rounded(number_after(text, "the worst joint distance from seed 000's closed form is "), number(ten[column(rows, "distance from seed 000")]), 2);
  }

  {  // step 8: the driving torque three ways; the sentence's agreements and range from the table
    const auto rows = lab.table("step8-driving-torque.csv");
    REQUIRE(rows.size() == 9);  // every 45 deg of a turn
    const std::size_t tau = column(rows, "tau by multipliers");
    double work = 0.0, potential = 0.0, low = INFINITY, high = -INFINITY;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      work = std::max(work, number(rows[r][3]));
      potential = std::max(potential, number(rows[r][5]));
      low = std::min(low, number(rows[r][tau])), high = std::max(high, number(rows[r][tau]));
      // Multipliers and virtual work are one torque to rounding; the potential's slope to the solver's tolerance.
      CHECK(number(rows[r][3]) < 1e-12);
      CHECK(number(rows[r][5]) < 1e-6);
    }
    CHECK_THAT(text, Contains(fmt::format("At these {} poses the driver torque", rows.size() - 1)));
    check_rounded(number_after(text, "is the virtual work's -sum F . v_J to "), work, 2);
    check_rounded(number_after(text, "central difference of the loads' potential to "), potential, 2);
    CHECK_THAT(text, Contains(fmt::format("runs from {:.4g} to {:.4g} N x length unit", low, high)));
  }

  {  // step 9: the quick-return's toggles and strokes against the closed form; the sentence from the tables
    const auto toggles = lab.table("step9-quick-return-toggles.csv");
    const auto strokes = lab.table("step9-quick-return-strokes.csv");
    REQUIRE(toggles.size() == 3);
    REQUIRE(strokes.size() == 4);
    const std::size_t brent = column(toggles, "crank by Brent (deg)"), travel = column(toggles, "C's travel");
    // whitworth.toml: r = 100, O2 45 above O4, the ram's line through O4: toggles where A crosses y = 0,
    // theta = -beta and 180 + beta, beta = asin(0.45); strokes 180 -+ 2 beta; C at 450 -+ 160.
    const double beta = std::asin(0.45) * 180.0 / std::acos(-1.0);
    double worst = 0.0;
    for (std::size_t r = 1; r < 3; ++r) {
      const double found = number(toggles[r][brent]);
      CHECK(std::min(std::abs(std::remainder(found + beta, 360.0)), std::abs(std::remainder(found - 180.0 - beta, 360.0))) < 1e-8);
      CHECK(std::abs(number(toggles[r][column(toggles, "closed form (deg)")]) - found) < 1e-8);
      worst = std::max(worst, number(toggles[r][column(toggles, "difference (deg)")]));
      CHECK(std::min(std::abs(number(toggles[r][travel]) - 290.0), std::abs(number(toggles[r][travel]) - 610.0)) < 1e-3);
    }
    const auto& slow = row_named(strokes, "slow stroke (deg of crank)");
    const auto& quick = row_named(strokes, "quick stroke (deg of crank)");
    const auto& ratio = row_named(strokes, "time ratio");
    const std::size_t by = column(strokes, "by Brent"), closed = column(strokes, "closed form");
    CHECK(std::abs(number(slow[closed]) - (180.0 + 2.0 * beta)) < 1e-8);
    CHECK(std::abs(number(quick[closed]) - (180.0 - 2.0 * beta)) < 1e-8);
    CHECK(std::abs(number(ratio[closed]) - (180.0 + 2.0 * beta) / (180.0 - 2.0 * beta)) < 1e-8);
    CHECK(std::abs(number(ratio[by]) - number(slow[by]) / number(quick[by])) < 1e-8);
    // The slow stroke starts at the toggle from which the crank, growing, turns more than 180 deg to the other.
    const double t1 = number(toggles[1][brent]), t2 = number(toggles[2][brent]);
    const bool from_first = std::fmod(t2 - t1 + 360.0, 360.0) >= 180.0;
    CHECK_THAT(text, Contains(fmt::format("C's forward (slow) stroke, from {} to {}", toggles[from_first ? 1 : 2][travel],
                                          toggles[from_first ? 2 : 1][travel])));
    CHECK_THAT(text, Contains(fmt::format("takes {:.4f} deg of crank and the return {:.4f} deg", number(slow[by]), number(quick[by]))));
    CHECK_THAT(text, Contains(fmt::format("= {0:.4f}, so C comes back {0:.4f} times faster", number(ratio[by]))));
    check_rounded(number_after(text, "the closed form's (sin theta = (y_O4 - y_O2) / r) to "), worst, 2);
    CHECK_THAT(text, Contains(fmt::format("and the time ratio is its {:.4f} to", number(ratio[closed]))));
  }
}

TEST_CASE("Linkage sentences: a Newton block, a slower sequential solve, a limit that is no fold", "[labs][sentences]") {
  const std::string model = derived_model_sentence(
      {"stephenson-iii.toml", 5, 10, 10, 1, {"crank, explicit", "body point, explicit", "Newton"}});
  CHECK_THAT(model, Contains("Of its 3 blocks, none is a dyad and 2 are explicit; 1 needs Newton") &&
                        Contains("--solver analytic does not apply"));
  CHECK_THAT(derived_model_sentence({"four-bar.toml", 3, 6, 6, 1, {"crank, explicit", "dyad, closed form (circle-circle)",
                                                                   "body point, explicit"}}),
             Contains("1 is a dyad in closed form and 2 are explicit; none needs Newton"));
  // Sequential twice as fast with twice the iterations: each iteration 4x cheaper.
  CHECK_THAT(sequential_against_full_sentence({"s", 1.0, 200}, {"f", 2.0, 100}, 12),
             Contains("2.00x faster than full Newton") && Contains("2.0x as many iterations") && Contains("4.0x less."));
  CHECK_THAT(sequential_against_full_sentence({"s", 4.0, 100}, {"f", 2.0, 100}, 8), Contains("each costs 2.0x more.") && Contains("GEPP on 8x8"));
  // kappa growing like 1/d (a cusp, not a fold): named as such.
  LimitApproach approach{10.0, 0.005, "block 2 (B from (A, Q): dyad, closed form (circle-circle))", "B",
                         {{1.0, 10.0, 100.0, 1.0}, {0.1, 1.0, 1000.0, 10.0}}};
  CHECK(measured_exponent(1.0, 100.0, 0.1, 1000.0) == Approx(-1.0));
  CHECK_THAT(limit_approach_sentence(approach, 1.0, 0.1),
             Contains("kappa(J) grows like d^-1.00") && Contains("not the square-root law"));
  approach.rows = {{1.0, 10.0, 100.0, 1.0}, {0.1, 10.0 / std::sqrt(10.0), 100.0 * std::sqrt(10.0), std::sqrt(10.0)}};
  CHECK_THAT(limit_approach_sentence(approach, 1.0, 0.1), Contains("d^-0.50") && Contains("within 0.1 of the square-root law"));
  // A quick-return twice as slow out as back: the ratio and its meaning from the strokes.
  const QuickReturnSummary quick{"ram", 240.0, 120.0, 2.0, 2.0 + 3e-12, 4e-13, 100.0, 400.0, "the closed form"};
  CHECK_THAT(quick_return_sentence(quick), Contains("ram's forward (slow) stroke, from 100 to 400") &&
                                               Contains("takes 240.0000 deg of crank and the return 120.0000 deg") &&
                                               Contains("ratio 240.0000 / 120.0000 = 2.0000, so ram comes back 2.0000 times faster") &&
                                               Contains("(the closed form) to 4e-13 deg") && Contains("its 2.0000 to 3e-12."));
  // No row at the distances asked for: no exponents claimed.
  CHECK_THAT(limit_approach_sentence(approach, 2.0, 0.2), !Contains("grows like"));
}
