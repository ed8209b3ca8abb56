// The profile mathematics (labs/bench/performance_profiles) on a hand-made table whose profiles
// are worked out below by hand from the definitions of Dolan & Moré and of Moré & Wild.

#include <catch2/catch.hpp>

#include <limits>
#include <stdexcept>

#include "bench/performance_profiles.hpp"

using namespace numlab::cli;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Four problems, two solvers. Problem 2 only solver 0 solves; problem 3 nobody solves.
//            solver 0  solver 1      ratios by hand: min of the row, then t / min
const CostTable costs = {{1.0, 2.0},  // min 1: 1, 2
                         {4.0, 2.0},  // min 2: 2, 1
                         {3.0, inf},  // min 3: 1, inf
                         {inf, inf}}; // nobody: inf, inf
const std::vector<int> sizes = {1, 3, 1, 2};  // n_p: n_p + 1 = 2, 4, 2, 3

}  // namespace

TEST_CASE("performance ratios: cost over the best cost of the row, infinite when unsolved", "[profiles]") {
  const CostTable ratios = performance_ratios(costs);
  const CostTable by_hand = {{1.0, 2.0}, {2.0, 1.0}, {1.0, inf}, {inf, inf}};
  CHECK(ratios == by_hand);
}

TEST_CASE("performance profile: the fraction of problems within a factor tau of the best", "[profiles]") {
  const CostTable ratios = performance_ratios(costs);
  // Solver 0: ratios 1, 2, 1, inf.  Solver 1: 2, 1, inf, inf.
  CHECK(performance_profile(ratios, 0, 1.0) == 0.5);    // fastest on problems 0 and 2
  CHECK(performance_profile(ratios, 0, 1.99) == 0.5);
  CHECK(performance_profile(ratios, 0, 2.0) == 0.75);   // and within 2x on problem 1
  CHECK(performance_profile(ratios, 0, 1e300) == 0.75); // never problem 3
  CHECK(performance_profile(ratios, 1, 1.0) == 0.25);
  CHECK(performance_profile(ratios, 1, 2.0) == 0.5);
  CHECK(performance_profile(ratios, 1, 1e300) == 0.5);
  CHECK(performance_profile(ratios, 0, 0.5) == 0.0);    // nobody beats the best
  CHECK(ratio_breakpoints(ratios) == std::vector<double>{1.0, 2.0});
}

TEST_CASE("data profile: the fraction solved within kappa (n + 1) evaluations", "[profiles]") {
  // Solver 0 needs kappa >= 1/2, 4/4, 3/2 on problems 0, 1, 2; solver 1 needs 2/2, 2/4 on 0, 1.
  CHECK(data_profile(costs, sizes, 0, 0.49) == 0.0);
  CHECK(data_profile(costs, sizes, 0, 0.5) == 0.25);
  CHECK(data_profile(costs, sizes, 0, 1.0) == 0.5);
  CHECK(data_profile(costs, sizes, 0, 1.5) == 0.75);
  CHECK(data_profile(costs, sizes, 0, 1e300) == 0.75);
  CHECK(data_profile(costs, sizes, 1, 0.5) == 0.25);
  CHECK(data_profile(costs, sizes, 1, 1.0) == 0.5);
  CHECK(data_profile(costs, sizes, 1, 1e300) == 0.5);
  CHECK(data_breakpoints(costs, sizes) == std::vector<double>{0.5, 1.0, 1.5});
}

TEST_CASE("profiles reject tables they cannot read", "[profiles]") {
  CHECK_THROWS_AS(performance_ratios({{1.0, 2.0}, {1.0}}), std::invalid_argument);
  CHECK_THROWS_AS(performance_ratios({{-1.0}}), std::invalid_argument);
  CHECK_THROWS_AS(performance_ratios({{std::numeric_limits<double>::quiet_NaN()}}), std::invalid_argument);
  CHECK_THROWS_AS(data_profile(costs, {1, 2}, 0, 1.0), std::invalid_argument);
  CHECK(performance_profile({}, 0, 1.0) == 0.0);
}
