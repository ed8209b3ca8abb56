// The four-bar and slider-crank analysis (crank_analysis.hpp): Grashof's classification, the toggles
// found by root finding against the law of cosines, the time ratio against (180 + alpha) / (180 - alpha),
// in the file's units, mm and km; and "not a four-bar" where the structure is another.

#include <catch2/catch.hpp>

#include <cmath>

#include "four_bar_text.hpp"
#include "model_files.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

constexpr double to_deg = 180.0 / pi;

double gap_deg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

CrankAnalysis analyse_text(const std::string& text, const std::string& output = {}) {
  const LinkageModel model(parse_linkage_description(text, "fb.toml"));
  const LinkageSolver solver(model, {});
  return analyse_crank_mechanism(solver, output);
}

// A crank-rocker with ground along +x and B above it: the rocker's extremes where crank and coupler
// are in line, |OB| = b + a at crank phi1, |OB| = b - a at crank 180 + phi2 (law of cosines in O, Q, B).
void check_crank_rocker(const CrankAnalysis& r, double a, double b, double c, double d, const std::string& rocker = "rocker") {
  const double phi1 = std::acos((d * d + (a + b) * (a + b) - c * c) / (2 * d * (a + b))) * to_deg;
  const double phi2 = std::acos((d * d + (b - a) * (b - a) - c * c) / (2 * d * (b - a))) * to_deg;
  const double alpha = phi2 - phi1, ratio = (180 + alpha) / (180 - alpha);
  CHECK(r.kind == "four-bar");
  CHECK(r.classification == "crank-rocker");
  CHECK(r.grashof);
  CHECK(r.shortest_name == "crank");
  CHECK(r.crank_turns_fully);
  CHECK(r.driver_toggles.empty());
  CHECK(r.output == rocker);
  REQUIRE(r.output_toggles.size() == 2);
  INFO("found " << r.output_toggles[0].crank_deg << ", " << r.output_toggles[1].crank_deg << "; closed form " << phi1 << ", "
                << 180 + phi2);
  CHECK(gap_deg(r.output_toggles[0].crank_deg, phi1) < 1e-7);
  CHECK(r.output_toggles[0].extended);
  CHECK(gap_deg(r.output_toggles[1].crank_deg, 180 + phi2) < 1e-7);
  CHECK_FALSE(r.output_toggles[1].extended);
  CHECK(std::abs(r.alpha_deg - alpha) < 2e-7);
  CHECK(std::abs(r.time_ratio - ratio) < 1e-8);
  CHECK(std::abs(r.time_ratio_closed_form - ratio) < 1e-12);
}

}  // namespace

TEST_CASE("A crank-rocker's toggles and time ratio by root finding match the law of cosines", "[crank-analysis]") {
  SECTION("four-bar.toml") {
    const LinkageModel model = model_file("four-bar");
    const LinkageSolver solver(model, {});
    check_crank_rocker(analyse_crank_mechanism(solver), 1.5, 4, 3.5, 4.5, "Q-B");
  }
  // 40, 120, 80, 100: s + l = 160 < p + q = 180, the crank shortest. phi1 = acos(0.9125) = 24.15 deg,
  // phi2 = acos(0.625) = 51.32 deg, alpha = 27.17 deg, time ratio 1.3556.
  SECTION("40, 120, 80, 100 mm") { check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1.0)), 40, 120, 80, 100); }
  SECTION("the same in km") { check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1e-6)), 40, 120, 80, 100); }
  SECTION("the same, 1e6 times larger") {
    check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1e6)), 40, 120, 80, 100);
  }
  SECTION("the reference pose elsewhere on the turn") {
    check_crank_rocker(analyse_text(four_bar_text(40, 120, 80, 100, 1.0, 250.0)), 40, 120, 80, 100);
  }
}

TEST_CASE("Grashof's classification names the kind by the shortest link", "[crank-analysis]") {
  // Ground shortest: a double-crank, no toggles, no time ratio.
  const CrankAnalysis double_crank = analyse_text(four_bar_text(3, 4, 3.5, 1.5, 1.0));
  CHECK(double_crank.classification == "double-crank");
  CHECK(double_crank.shortest_name == "ground");
  CHECK(double_crank.crank_turns_fully);
  CHECK(double_crank.output_toggles.empty());
  CHECK(std::isnan(double_crank.time_ratio));
  // Coupler shortest: a Grashof double-rocker; the crank stops where coupler and rocker line up.
  const CrankAnalysis double_rocker = analyse_text(four_bar_text(3, 1.5, 3.5, 4, 1.0, 90.0));
  CHECK(double_rocker.classification == "double-rocker");
  CHECK(double_rocker.grashof);
  CHECK_FALSE(double_rocker.crank_turns_fully);
  // The parallelogram: s + l = p + q, a change point.
  CHECK(analyse_text(four_bar_text(2, 4, 2, 4, 1.0)).classification == "change point");
}

TEST_CASE("A non-Grashof four-bar's crank stops at its toggles: arccos((a^2 + d^2 - (b + c)^2) / 2ad)", "[crank-analysis]") {
  // Crank 2, coupler 3, rocker 2.5, ground 4 (docs/linkage-files.md's limit example): s + l = 6 > 5.5.
  for (double scale : {1.0, 1e-6, 1e6}) {
    const CrankAnalysis r = analyse_text(four_bar_text(2, 3, 2.5, 4, scale));
    const double toggle = std::acos((4.0 + 16.0 - 5.5 * 5.5) / 16.0) * to_deg;  // 129.838 deg
    CHECK(r.classification == "triple-rocker (non-Grashof)");
    CHECK_FALSE(r.grashof);
    CHECK_FALSE(r.crank_turns_fully);
    REQUIRE(r.driver_toggles.size() == 2);  // |b - c| = 0.5 is never reached: (4 + 16 - 0.25) / 16 > 1
    CHECK(gap_deg(r.driver_toggles[0].crank_deg, toggle) < 1e-7);
    CHECK(gap_deg(r.driver_toggles[1].crank_deg, -toggle) < 1e-7);
    CHECK(std::isnan(r.time_ratio));
    // The rocker's extremes inside that range: crank and coupler in line, |OB| = a + b = 5 (|OB| = 1
    // cannot close with the rocker): crank at +-acos((16 + 25 - 6.25) / 40) = +-29.66 deg.
    const double extended = std::acos((16.0 + 25.0 - 6.25) / 40.0) * to_deg;
    REQUIRE_FALSE(r.output_toggles.empty());
    for (const Toggle& t : r.output_toggles) {
      CHECK(std::min(gap_deg(t.crank_deg, extended), gap_deg(t.crank_deg, -extended)) < 1e-7);
      CHECK(t.extended);
    }
  }
}

TEST_CASE("The offset slider-crank's dead centres and quick-return ratio match the closed form", "[crank-analysis]") {
  // r = 1, l = 3.2, e = 0.4: extended at atan2(e, sqrt((l + r)^2 - e^2)) = 5.465 deg, folded at
  // 180 + atan2(e, sqrt((l - r)^2 - e^2)) = 190.476 deg; alpha = 5.011 deg, time ratio 1.0573.
  const LinkageModel model = model_file("slider-crank");
  const LinkageSolver solver(model, {});
  const CrankAnalysis r = analyse_crank_mechanism(solver);
  const double ext = std::atan2(0.4, std::sqrt(4.2 * 4.2 - 0.16)) * to_deg;
  const double fold = 180.0 + std::atan2(0.4, std::sqrt(2.2 * 2.2 - 0.16)) * to_deg;
  const double alpha = fold - ext - 180.0;
  CHECK(r.kind == "slider-crank");
  CHECK(r.output == "S");
  CHECK(r.crank_turns_fully);
  CHECK(r.driver_toggles.empty());
  REQUIRE(r.output_toggles.size() == 2);
  CHECK(gap_deg(r.output_toggles[0].crank_deg, ext) < 1e-7);
  CHECK(gap_deg(r.output_toggles[1].crank_deg, fold) < 1e-7);
  CHECK(gap_deg(r.output_toggles[0].closed_form_deg, ext) < 1e-10);
  CHECK(std::abs(r.time_ratio - (180 + alpha) / (180 - alpha)) < 1e-8);
}

TEST_CASE("A mechanism that is not a four-bar is said to be one, and not analysed", "[crank-analysis]") {
  for (const std::string name : {"jansen", "watt-i", "klann"}) {
    const LinkageModel model = model_file(name);
    const LinkageSolver solver(model, {});
    const CrankAnalysis r = analyse_crank_mechanism(solver);
    INFO(name << ": " << r.not_analysed);
    CHECK(r.kind.empty());
    CHECK(r.not_analysed.rfind("not a four-bar: ", 0) == 0);
  }
  const LinkageModel model = model_file("four-bar");
  const LinkageSolver solver(model, {});
  CHECK_THROWS_WITH(analyse_crank_mechanism(solver, "X"),
                    "unknown output 'X': name one of the links O-A, A-B, Q-B");
  // Another output: the coupler stands still (omega 0) at its own toggles; no closed form is claimed.
  const CrankAnalysis coupler = analyse_crank_mechanism(solver, "A-B");
  CHECK(coupler.output == "A-B");
  for (const Toggle& t : coupler.output_toggles) CHECK(std::isnan(t.closed_form_deg));
}
