// The closed forms of the shipped one-driver models (numlab/mechanisms/closed_forms/) against
// themselves: each pose keeps the mechanism's lengths and contacts, each velocity and acceleration
// (points and angles) matches the 5-point central differences of the closed form's own positions,
// each quick-return's output stands still at its toggles, and the boom's cylinder force by moments
// matches virtual work. Checked in the models' own units and scaled by 1e-3 and 1e3.

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "numlab/mechanisms/closed_forms/hydraulic_boom.hpp"
#include "numlab/mechanisms/closed_forms/inverted_slider_crank.hpp"
#include "numlab/mechanisms/closed_forms/watt_linkage.hpp"
#include "numlab/mechanisms/closed_forms/whitworth.hpp"

using namespace numlab::mechanisms::closed_forms;

namespace {

// One named quantity of a pose: a point or an angle.
struct Track {
  const char* name;
  std::function<PointMotion(double)> point;   // empty for an angle
  std::function<AngleMotion(double)> angle;   // empty for a point
};

// 5-point central differences, O(h^4): f' = (-f(2) + 8 f(1) - 8 f(-1) + f(-2)) / 12 h,
// f'' = (-f(2) + 16 f(1) - 30 f(0) + 16 f(-1) - f(-2)) / 12 h^2. Angles are unwrapped about f(0).
template <class F>
std::pair<Eigen::Vector2d, Eigen::Vector2d> differences(const F& f, double t, double h) {
  const Eigen::Vector2d m2 = f(t - 2 * h), m1 = f(t - h), c = f(t), p1 = f(t + h), p2 = f(t + 2 * h);
  return {(-p2 + 8.0 * p1 - 8.0 * m1 + m2) / (12.0 * h), (-p2 + 16.0 * p1 - 30.0 * c + 16.0 * m1 - m2) / (12.0 * h * h)};
}

// Every track's derivatives against differences at driver t; `size` is the mechanism's size in its
// units (velocities and accelerations are compared relative to it: per radian, lengths scale with it).
void check_derivatives(const std::vector<Track>& tracks, double t, double h, double size) {
  for (const Track& track : tracks) {
    INFO(track.name << " at driver " << t);
    if (track.point) {
      const auto [v, a] = differences([&](double x) { return track.point(x).p; }, t, h);
      const PointMotion m = track.point(t);
      REQUIRE(std::isfinite(m.v.norm() + m.a.norm()));
      CHECK((m.v - v).norm() <= 1e-9 * size);
      CHECK((m.a - a).norm() <= 1e-6 * size);
    } else {
      const double centre = track.angle(t).angle;
      const auto unwrapped = [&](double x) {
        return Eigen::Vector2d(centre + std::remainder(track.angle(x).angle - centre, 2.0 * pi), 0.0);
      };
      const auto [v, a] = differences(unwrapped, t, h);
      const AngleMotion m = track.angle(t);
      REQUIRE(std::isfinite(m.omega + m.alpha));
      CHECK(std::abs(m.omega - v.x()) <= 1e-9 * (1.0 + std::abs(m.omega)));
      CHECK(std::abs(m.alpha - a.x()) <= 1e-6 * (1.0 + std::abs(m.alpha)));
    }
  }
}

// The models' numbers (as the shipped files), times `scale`.
InvertedSliderCrank inverted(double scale) { return {{0.0, 0.0}, {0.0, -100.0 * scale}, 40.0 * scale, 180.0 * scale}; }
Whitworth quick_return(double scale) { return {{0.0, 45.0 * scale}, {0.0, 0.0}, 100.0 * scale, 160.0 * scale, 450.0 * scale, 0.0, 1}; }
HydraulicBoom boom(double scale) {
  return {{0.0, 0.0}, {0.9 * scale, -0.6 * scale}, 1.5 * scale, std::hypot(3.9, 0.5) * scale, std::atan2(0.5, 3.9), 1};
}
WattLinkage watt(double scale) { return {{-100.0 * scale, 30.0 * scale}, {100.0 * scale, -30.0 * scale}, 100.0 * scale, 60.0 * scale, 100.0 * scale, 0.5, -1}; }

constexpr double deg = pi / 180.0;

}  // namespace

TEST_CASE("closed forms: the inverted slider-crank keeps its lengths, A on the rocker, and its derivatives match differences",
          "[closed_forms]") {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const InvertedSliderCrank m = inverted(scale);
    for (double t = 0.0; t < 2.0 * pi; t += 7.0 * deg) {
      const InvertedSliderCrankPose pose = inverted_slider_crank(m, t);
      CHECK(std::abs((pose.A.p - m.O).norm() - m.crank) <= 1e-14 * 180.0 * scale);
      CHECK(std::abs((pose.C.p - m.B).norm() - m.rocker) <= 1e-14 * 180.0 * scale);
      CHECK(std::abs(cross((pose.C.p - m.B).normalized(), pose.A.p - m.B)) <= 1e-14 * 180.0 * scale);
      CHECK((pose.C.p - m.B).dot(pose.A.p - m.B) > 0.0);
      CHECK(std::abs(pose.slide - (pose.A.p - m.B).norm()) <= 1e-14 * 180.0 * scale);
      const std::vector<Track> tracks = {
          {"A", [&](double x) { return inverted_slider_crank(m, x).A; }, {}},
          {"C", [&](double x) { return inverted_slider_crank(m, x).C; }, {}},
          {"rocker", {}, [&](double x) { return inverted_slider_crank(m, x).rocker; }},
          {"slide", [&](double x) {
             const auto p = inverted_slider_crank(m, x);
             return PointMotion{{p.slide, 0.0}, {p.slide_rate, 0.0}, {p.slide_acceleration, 0.0}};
           }, {}}};
      check_derivatives(tracks, t, 1e-3, 180.0 * scale);
    }
  }
}

TEST_CASE("closed forms: the inverted slider-crank's rocker stands still at its toggles, time ratio (pi - gamma) / gamma",
          "[closed_forms]") {
  const InvertedSliderCrank m = inverted(1.0);
  const QuickReturn q = inverted_slider_crank_quick_return(m);
  // gamma = acos(40 / 100) = 66.4218 deg: 1.71 = (180 - 66.42) / 66.42.
  CHECK(q.time_ratio == Approx((180.0 - std::acos(0.4) / deg) / (std::acos(0.4) / deg)).epsilon(1e-14));
  for (const double toggle : {q.toggle_1, q.toggle_2}) {
    const InvertedSliderCrankPose pose = inverted_slider_crank(m, toggle);
    CHECK(std::abs(pose.rocker.omega) <= 1e-14);
    CHECK(std::abs((pose.A.p - m.O).dot(pose.A.p - m.B)) <= 1e-12 * 100.0 * 100.0);  // OA perpendicular to BA
    // An extreme: the rocker's angle is further from vertical than at the neighbouring crank angles.
    const double here = std::abs(pose.rocker.angle - pi / 2.0);
    CHECK(here > std::abs(inverted_slider_crank(m, toggle + 0.01).rocker.angle - pi / 2.0));
    CHECK(here > std::abs(inverted_slider_crank(m, toggle - 0.01).rocker.angle - pi / 2.0));
  }
  // The longer crank travel between the toggles over the shorter.
  const double arc = std::remainder(q.toggle_2 - q.toggle_1, 2.0 * pi);
  const double longer = 2.0 * pi - std::abs(arc), shorter = std::abs(arc);
  CHECK(q.time_ratio == Approx(longer / shorter).epsilon(1e-13));
}

TEST_CASE("closed forms: the Whitworth quick-return keeps its lengths and contacts, and its derivatives match differences",
          "[closed_forms]") {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const Whitworth m = quick_return(scale);
    const double size = 450.0 * scale;
    for (double t = 0.0; t < 2.0 * pi; t += 7.0 * deg) {
      const WhitworthPose pose = whitworth(m, t);
      CHECK(std::abs((pose.A.p - m.O2).norm() - m.crank) <= 1e-14 * size);
      CHECK(std::abs((pose.B.p - m.O4).norm() - m.slot) <= 1e-14 * size);
      CHECK(std::abs(cross((pose.B.p - m.O4).normalized(), pose.A.p - m.O4)) <= 1e-14 * size);
      CHECK(std::abs((pose.C.p - pose.B.p).norm() - m.rod) <= 1e-14 * size);
      CHECK(pose.C.p.y() == m.ram_height);
      CHECK(pose.C.p.x() > pose.B.p.x());
      const std::vector<Track> tracks = {
          {"A", [&](double x) { return whitworth(m, x).A; }, {}},
          {"B", [&](double x) { return whitworth(m, x).B; }, {}},
          {"C", [&](double x) { return whitworth(m, x).C; }, {}},
          {"slot", {}, [&](double x) { return whitworth(m, x).slot; }},
          {"rod", {}, [&](double x) { return whitworth(m, x).rod; }}};
      check_derivatives(tracks, t, 1e-3, size);
    }
  }
}

TEST_CASE("closed forms: the Whitworth ram stands still at its toggles, time ratio (pi + 2 beta) / (pi - 2 beta)",
          "[closed_forms]") {
  const Whitworth m = quick_return(1.0);
  const QuickReturn q = whitworth_quick_return(m);
  const double beta = std::asin(45.0 / 100.0);  // 26.7437 deg: 233.49 / 126.51 = 1.8456
  CHECK(q.time_ratio == Approx((pi + 2.0 * beta) / (pi - 2.0 * beta)).epsilon(1e-14));
  double stroke_end[2] = {0.0, 0.0};
  int k = 0;
  for (const double toggle : {q.toggle_1, q.toggle_2}) {
    const WhitworthPose pose = whitworth(m, toggle);
    CHECK(std::abs(pose.C.v.x()) <= 1e-12 * 450.0);
    stroke_end[k++] = pose.C.p.x();
  }
  // The toggles are the ram's extremes: l - R and l + R, 320 mm apart, and no crank angle beyond them.
  CHECK(std::min(stroke_end[0], stroke_end[1]) == Approx(450.0 - 160.0).epsilon(1e-14));
  CHECK(std::max(stroke_end[0], stroke_end[1]) == Approx(450.0 + 160.0).epsilon(1e-14));
  for (double t = 0.0; t < 2.0 * pi; t += 0.5 * deg) {
    CHECK(whitworth(m, t).C.p.x() >= 290.0 - 1e-12);
    CHECK(whitworth(m, t).C.p.x() <= 610.0 + 1e-12);
  }
  const double arc = std::remainder(q.toggle_2 - q.toggle_1, 2.0 * pi);
  CHECK(q.time_ratio == Approx((2.0 * pi - std::abs(arc)) / std::abs(arc)).epsilon(1e-13));
  Whitworth raised = m;
  raised.ram_height = 10.0;
  CHECK_THROWS_AS(whitworth_quick_return(raised), std::invalid_argument);
}

TEST_CASE("closed forms: the hydraulic boom keeps its lengths, its derivatives match differences, the cylinder force by moments is virtual work's",
          "[closed_forms]") {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const HydraulicBoom m = boom(scale);
    const double size = 4.0 * scale;
    for (double s = 1.2 * scale; s <= 2.2 * scale; s += 0.05 * scale) {
      const HydraulicBoomPose pose = hydraulic_boom(m, s);
      CHECK(std::abs((pose.B.p - m.P).norm() - s) <= 1e-14 * size);
      CHECK(std::abs((pose.B.p - m.O).norm() - m.pin) <= 1e-14 * size);
      CHECK(std::abs((pose.T.p - m.O).norm() - m.tip) <= 1e-14 * size);
      CHECK(std::abs((pose.T.p - pose.B.p).norm() - std::hypot(2.4, 0.5) * scale) <= 1e-14 * size);
      CHECK(cross(m.P - m.O, pose.B.p - m.O) > 0.0);  // B to the left of O -> P: the boom up
      // Per unit of length the rates carry 1 / scale: compare them in the scale-free driver s / scale.
      const std::vector<Track> tracks = {
          {"B", [&](double x) { return hydraulic_boom(m, x * scale).B; }, {}},
          {"T", [&](double x) { return hydraulic_boom(m, x * scale).T; }, {}},
          {"boom", {}, [&](double x) { return hydraulic_boom(m, x * scale).boom; }},
          {"cylinder", {}, [&](double x) { return hydraulic_boom(m, x * scale).cylinder; }}};
      for (const Track& track : tracks) {
        INFO(track.name << " at s = " << s);
        const double x = s / scale, h = 1e-3;
        if (track.point) {
          const auto [v, a] = differences([&](double y) { return track.point(y).p; }, x, h);
          const PointMotion p = track.point(x);
          CHECK((p.v * scale - v).norm() <= 1e-9 * size);
          CHECK((p.a * scale * scale - a).norm() <= 1e-6 * size);
        } else {
          const auto [v, a] = differences([&](double y) { return Eigen::Vector2d(track.angle(y).angle, 0.0); }, x, h);
          const AngleMotion p = track.angle(x);
          CHECK(std::abs(p.omega * scale - v.x()) <= 1e-9 * (1.0 + std::abs(v.x())));
          CHECK(std::abs(p.alpha * scale * scale - a.x()) <= 1e-6 * (1.0 + std::abs(a.x())));
        }
      }
      // 500 kg at the tip: the push by moments about O against -F . T' (virtual work).
      const Eigen::Vector2d weight(0.0, -500.0 * 9.80665);
      const double push = cylinder_force(m, pose, weight);
      CHECK(push > 0.0);
      CHECK(push == Approx(-weight.dot(pose.T.v)).epsilon(1e-12));
    }
  }
}

TEST_CASE("closed forms: Watt's linkage keeps its lengths, M midway, its derivatives match differences, M runs nearly straight",
          "[closed_forms]") {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const WattLinkage m = watt(scale);
    const double size = 100.0 * scale;
    for (double t = -25.0 * deg; t <= 25.0 * deg; t += 2.5 * deg) {
      const WattPose pose = watt_linkage(m, t);
      CHECK(std::abs((pose.B.p - m.O1).norm() - m.rocker_1) <= 1e-14 * size);
      CHECK(std::abs((pose.C.p - pose.B.p).norm() - m.coupler) <= 1e-13 * size);
      CHECK(std::abs((pose.C.p - m.O2).norm() - m.rocker_2) <= 1e-14 * size);
      CHECK((pose.M.p - 0.5 * (pose.B.p + pose.C.p)).norm() <= 1e-14 * size);
      CHECK(std::abs(pose.coupler.angle - std::atan2(pose.C.p.y() - pose.B.p.y(), pose.C.p.x() - pose.B.p.x())) <= 1e-13);
      const std::vector<Track> tracks = {
          {"B", [&](double x) { return watt_linkage(m, x).B; }, {}},
          {"C", [&](double x) { return watt_linkage(m, x).C; }, {}},
          {"M", [&](double x) { return watt_linkage(m, x).M; }, {}},
          {"coupler", {}, [&](double x) { return watt_linkage(m, x).coupler; }},
          {"rocker 2", {}, [&](double x) { return watt_linkage(m, x).rocker_2; }}};
      check_derivatives(tracks, t, 1e-3, size);
    }
    // At the reference pose B, M, C stand on x = 0 and M moves straight up: M' = (0, v).
    const WattPose middle = watt_linkage(m, 0.0);
    CHECK(middle.M.p.norm() <= 1e-13 * size);
    CHECK(std::abs(middle.M.v.x()) <= 1e-13 * size);
    // Over +-10 degrees of the rocker M leaves the line x = 0 by under 0.01 % of the rocker's length
    // (0.0069 mm of 100) while it travels a third of it (34.73 mm).
    double worst = 0.0;
    for (double t = -10.0 * deg; t <= 10.0 * deg; t += 0.25 * deg) worst = std::max(worst, std::abs(watt_linkage(m, t).M.p.x()));
    CHECK(worst <= 1e-4 * size);
    CHECK(worst >= 5e-5 * size);  // but not exactly straight: Watt's is an approximate straight line
    CHECK(watt_linkage(m, 10.0 * deg).M.p.y() - watt_linkage(m, -10.0 * deg).M.p.y() > 0.3 * size);
  }
}
