// The lab's sentence builders say what their numbers say.

#include <catch2/catch.hpp>

#include <limits>

#include "basins/basin_sentences.hpp"

using namespace numlab::basins;
using Catch::Matchers::Contains;

TEST_CASE("Basin sentences name the measured shares and directions", "[basins][sentences]") {
  CHECK(percent(1, 8) == "12.5%");
  CHECK_THAT(damping_sentence(10, 20, 100, 30, 5), Contains("raises") && Contains("from 10.0% to 20.0%") &&
                                                      Contains("fewer failing starts (5 against 30)"));
  CHECK_THAT(damping_sentence(20, 10, 100, 5, 30), Contains("lowers") && Contains("more failing"));
  CHECK_THAT(damping_sentence(20, 20, 100, 5, 5), Contains("keeps") && Contains("as many"));
  const double none = std::numeric_limits<double>::infinity();
  CHECK_THAT(stray_sentence("plain", 0.5, none, 0.01), Contains("0.5 rad from the solution") &&
                                                          Contains("no start fails"));
  CHECK_THAT(stray_sentence("plain", none, 0.25, 0.01), Contains("no start on the slice lands on another branch"));
  CHECK_THAT(seed_position_sentence(0.0123, false, "B- C- D+ E-"), Contains("0.0123 rad") && Contains("another branch"));
}
