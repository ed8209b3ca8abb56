#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "numlab/mechanisms/anchored_sincos.hpp"

using numlab::mechanisms::AnchoredSinCos;

TEST_CASE("Anchored sines and cosines agree with the library to a few ulp, without drift", "[mechanisms][sincos]") {
  AnchoredSinCos<3> sines;
  std::mt19937 random(7);
  // Moves of every size: across many table nodes, a few nodes, Newton-sized and none.
  std::uniform_real_distribution<double> far(-3.0, 3.0), near(-0.07, 0.07), tiny(-1e-6, 1e-6);
  Eigen::Vector3d theta(0.3, 2.9, -5.0), c, s;
  double worst = 0.0;
  for (int call = 0; call < 30000; ++call) {
    for (int k = 0; k < 3; ++k) {
      const int kind = (call + k) % 10;
      theta(k) += kind == 0 ? far(random) : kind < 5 ? near(random) : kind < 9 ? tiny(random) : 0.0;
      if (std::abs(theta(k)) > 30.0) theta(k) = std::copysign(20.0, -theta(k));  // stay within the table
    }
    sines.evaluate(theta, c, s);
    for (int k = 0; k < 3; ++k) {
      worst = std::max({worst, std::abs(c(k) - std::cos(theta(k))), std::abs(s(k) - std::sin(theta(k)))});
    }
  }
  CHECK(worst <= 4.0 * std::numeric_limits<double>::epsilon());
  CHECK(worst > 0.0);  // the rotations were used (the library alone would agree exactly)
}

TEST_CASE("Anchored sines and cosines: every node of the table, halfway between nodes, and beyond it",
          "[mechanisms][sincos]") {
  constexpr double limit = AnchoredSinCos<1>::table_limit;
  double worst = 0.0;
  // Fresh caches, so every angle takes the table path: nodes, quarter and half steps, both signs,
  // one angle alone and two at once.
  for (double t = -limit; t <= limit; t += 1.0 / 256) {
    AnchoredSinCos<1> one;
    AnchoredSinCos<2> two;
    Eigen::Matrix<double, 1, 1> c1, s1;
    Eigen::Vector2d c2, s2;
    const Eigen::Vector2d pair(t, -t / 3.0);
    one.evaluate(Eigen::Matrix<double, 1, 1>(t), c1, s1);
    two.evaluate(pair, c2, s2);
    worst = std::max({worst, std::abs(c1(0) - std::cos(t)), std::abs(s1(0) - std::sin(t))});
    for (int k = 0; k < 2; ++k) {
      worst = std::max({worst, std::abs(c2(k) - std::cos(pair(k))), std::abs(s2(k) - std::sin(pair(k)))});
    }
  }
  CHECK(worst <= 2.0 * std::numeric_limits<double>::epsilon());
  // Beyond the table the library's own values, for both angles of a pair with one beyond it.
  AnchoredSinCos<2> sines;
  Eigen::Vector2d c, s;
  const Eigen::Vector2d beyond(limit + 0.5, 0.75);
  sines.evaluate(beyond, c, s);
  CHECK(c(0) == std::cos(beyond(0)));
  CHECK(s(0) == std::sin(beyond(0)));
  CHECK(c(1) == std::cos(beyond(1)));  // 0.75 is a node: the table's value, the library's
  CHECK(s(1) == std::sin(beyond(1)));
  sines.evaluate(Eigen::Vector2d(-1000.25, 0.75 + 1e-3), c, s);
  CHECK(c(0) == std::cos(-1000.25));
  CHECK(s(0) == std::sin(-1000.25));
  CHECK(std::abs(c(1) - std::cos(0.75 + 1e-3)) <= 2.0 * std::numeric_limits<double>::epsilon());
}

TEST_CASE("Anchored sines and cosines of non-finite angles are NaN, as the library's", "[mechanisms][sincos]") {
  AnchoredSinCos<2> sines;
  Eigen::Vector2d c, s;
  sines.evaluate(Eigen::Vector2d(1.0, INFINITY), c, s);
  CHECK(c(0) == std::cos(1.0));
  CHECK(std::isnan(c(1)));
  CHECK(std::isnan(s(1)));
  sines.evaluate(Eigen::Vector2d(1.0 + 1e-3, 0.5), c, s);  // a finite angle again comes from the table
  CHECK(std::abs(c(1) - std::cos(0.5)) <= std::numeric_limits<double>::epsilon());
  CHECK(std::abs(c(0) - std::cos(1.0 + 1e-3)) <= 2.0 * std::numeric_limits<double>::epsilon());
}
