// The sentence builders of labs/lessons/lab_sentences.hpp, fed numbers the labs have printed (cases
// where a fixed text would contradict them) and the cases on either side of each threshold.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "lessons/lab_sentences.hpp"

using Catch::Matchers::Contains;
using namespace numlab::cli;

TEST_CASE("The Hilbert sentence names the first n with kappa > 1/eps, from the rows", "[labs][sentences]") {
  // The gauss lab's rows: n = 12 already has kappa 3.8e16 > 1/eps; n = 13 is singular.
  const std::vector<ConditionRow> rows = {{10, 3.54e13, false}, {12, 3.83e16, false}, {13, 4.63e17, true}};
  const std::string text = condition_limit_sentence(rows);
  CHECK_THAT(text, Contains("at n = 12 (kappa 3.83e+16)") && Contains("'singular' at n = 13") &&
                       Contains("At n = 12 it still returns an answer"));
  // Neither limit reached.
  CHECK_THAT(condition_limit_sentence({{4, 2.8e4, false}, {8, 3.4e10, false}}),
             Contains("Up to n = 8 kappa stays below") && Contains("never says 'singular' up to n = 8"));
}

TEST_CASE("The PA = LU sentence: exact, to rounding, or beyond it, from max|PA - LU|", "[labs][sentences]") {
  const double eps = std::numeric_limits<double>::epsilon();
  // The gauss lab's 3x3: max|PA - LU| = 1.11e-16 against max|a_ij| = 3, growth 1.
  CHECK_THAT(lu_factors_sentence(1.11e-16, 3.0, 3, 1.0),
             Contains("to rounding: max|PA - LU| / max|a_ij| = 3.7e-17, within n*eps*growth = 6.7e-16"));
  CHECK_THAT(lu_factors_sentence(0.0, 3.0, 3, 1.0), Contains("exactly") && !Contains("rounding"));
  // Either side of n*eps*growth (growth below 1 counts as 1; above, it widens the bound).
  CHECK_THAT(lu_factors_sentence(0.99 * 3 * eps, 1.0, 3, 0.5), Contains("to rounding"));
  CHECK_THAT(lu_factors_sentence(1.01 * 3 * eps, 1.0, 3, 0.5), Contains("only to") && Contains("beyond"));
  CHECK_THAT(lu_factors_sentence(1e-10, 1.0, 3, 1e7), Contains("to rounding"));
  CHECK_THAT(lu_factors_sentence(1e-10, 1.0, 3, 1e5), Contains("only to 1e-10 relative"));
}

TEST_CASE("Digits lost are log10(forward error / eps), judged against kappa * eps", "[labs][sentences]") {
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(digits_lost(3.17e-11) == Approx(std::log10(3.17e-11 / eps)));
  CHECK(digits_lost(1e-17) == 0.0);
  // GSL LU's forward error of 3e-11 on a nearly singular system: 5.2 digits lost, not "every digit kept".
  CHECK_THAT(digits_lost_sentence("GSL LU", 3.17e-11, "d = 1e-06", 4e6),
             Contains("3.17e-11, at d = 1e-06: 5.2 digits lost") && Contains("within the kappa * eps = 8.9e-10"));
  CHECK_THAT(digits_lost_sentence("X", 1e-3, "d = 1", 10.0), Contains("beyond"));
  CHECK_THAT(digits_lost_sentence("X", 1e-17, "d = 1", 10.0), Contains("no digit lost"));
}

TEST_CASE("The loop sentence says where the loop stopped, and never 'never' when it did", "[labs][sentences]") {
  const std::vector<LoopOutcome> with_stop = {{50.05, false, 500, 3.0}, {52.92, true, 220, 4.6}, {55.78, false, 500, 2.0}};
  const std::string text = loop_stops_sentence(3, with_stop, 500);
  CHECK_THAT(text, Contains("without stopping at 2 of 3 angles") && Contains("stops only at 52.92 deg (after 220") &&
                       Contains("not a root") && !Contains("never"));
  const std::vector<LoopOutcome> none = {{50.05, false, 500, 3.0}, {55.78, false, 500, 2.0}};
  CHECK_THAT(loop_stops_sentence(3, none, 500), Contains("all 2 angles") && Contains("never stops"));
  const std::vector<LoopOutcome> singular = {{50.05, false, 12, 3.0}, {55.78, false, 500, 2.0}};
  CHECK_THAT(loop_stops_sentence(3, singular, 500), Contains("fails at all 2 angles (1 of them after all 500"));
}

TEST_CASE("Speed sentences say which is faster, by the measured ratio, and why", "[labs][sentences]") {
  CHECK(speed_ratio_phrase(1.0, 2.07) == "2.07x faster than");
  CHECK(speed_ratio_phrase(1.46, 1.0) == "1.46x slower than");
  CHECK(speed_ratio_phrase(1.0, 1.005) == "as fast as");
  // Measured Jansen numbers: sequential 2.07x faster, with more but cheaper iterations.
  const std::string blocks = block_newton_sentence({"sequential Newton", 1e-4, 1462}, {"full Newton", 2.07e-4, 379}, 8);
  CHECK_THAT(blocks, Contains("Sequential Newton is 2.07x faster than full Newton") &&
                         Contains("3.9x as many iterations (1462 block iterations against 379)") &&
                         Contains("each costs 8.0x less") && Contains("8x8 Jacobian"));
  // Slower: the sentence turns round.
  CHECK_THAT(block_newton_sentence({"sequential Newton", 3e-4, 1462}, {"full Newton", 2e-4, 379}, 8),
             Contains("1.50x slower than") && Contains("each costs 2.6x less"));
  CHECK_THAT(same_method_sentence({"full Newton", 1e-4, 379}, {"GSL's newton", 3e-4, 380}),
             Contains("3.00x faster than GSL's newton") && Contains("the cost of each iteration"));
  CHECK_THAT(same_method_sentence({"full Newton", 1e-4, 200}, {"GSL's newton", 3e-4, 400}),
             Contains("per iteration, full Newton is 1.50x faster than"));
  CHECK_THAT(closed_form_sentence({"full Newton", 1.46, 379}, {"the closed form", 1.0, 0}, 360),
             Contains("Full Newton is 1.46x slower than the closed form") && Contains("1.05 iterations per pose"));
}

TEST_CASE("Trends and counts say what the numbers do", "[labs][sentences]") {
  CHECK(trend_phrase({4.25, 2.75, 1.18}) == "falls at every step, from 4.25 to 1.18");
  CHECK(trend_phrase({1.0, 3.0, 2.0, 0.5}) == "falls overall, from 1 to 0.5, rising at 1 of 3 steps");
  CHECK(trend_phrase({1.0, 2.0}) == "rises at every step, from 1 to 2");
  CHECK(count_of(6, 6) == "all 6");
  CHECK(count_of(0, 6) == "none of the 6");
  CHECK(count_of(5, 6) == "5 of 6");
}
