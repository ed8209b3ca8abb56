#pragma once
// Linkage descriptions built in C++ for the model and solver tests (the file reader has its own
// tests): a Grashof four-bar, a non-Grashof four-bar, an offset slider-crank, and broken ones.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms::testing {

struct DescriptionBuilder {
  LinkageDescription d;
  explicit DescriptionBuilder(std::string name) {
    d.file = name + ".toml";
    d.name = std::move(name);
  }
  int ground(const std::string& name, double x, double y) {
    d.joints.push_back({name, true, Eigen::Vector2d(x, y), {static_cast<int>(d.joints.size()) + 1, 1}});
    return static_cast<int>(d.joints.size()) - 1;
  }
  int joint(const std::string& name, double x, double y) {
    d.joints.push_back({name, false, Eigen::Vector2d(x, y), {static_cast<int>(d.joints.size()) + 1, 1}});
    return static_cast<int>(d.joints.size()) - 1;
  }
  void link(int a, int b, double length) { d.links.push_back({a, b, length, {40 + static_cast<int>(d.links.size()), 1}}); }
  void body(const std::string& name, std::vector<int> joints, std::vector<Eigen::Vector2d> local) {
    d.bodies.push_back({name, std::move(joints), std::move(local), {60 + static_cast<int>(d.bodies.size()), 1}});
  }
  void slider(int joint, double x, double y, double angle_deg) {
    d.sliders.push_back({joint, Eigen::Vector2d(x, y), angle_deg, {80 + static_cast<int>(d.sliders.size()), 1}});
  }
  void crank(int pivot, int joint, double angle_deg) {
    d.driver = {.kind = DriverKind::crank, .pivot = pivot, .joint = joint, .reference = angle_deg, .place = {90, 1}};
  }
  void slider_driver(int slider, double travel) {
    d.driver = {.kind = DriverKind::slider,
                .joint = d.sliders[static_cast<std::size_t>(slider)].joint,
                .slider = slider,
                .reference = travel,
                .place = {90, 1}};
  }
};

// Four-bar O-A-B-Q: crank a = |OA|, coupler b = |AB|, rocker c = |QB|, ground d = |OQ| along +x.
// The rough positions put B above the ground line (the open assembly, seen from O).
inline LinkageDescription four_bar(double a, double b, double c, double d, double crank_deg) {
  DescriptionBuilder m("four-bar");
  const int O = m.ground("O", 0, 0), Q = m.ground("Q", d, 0);
  const double t = crank_deg * std::numbers::pi / 180.0;
  const int A = m.joint("A", a * std::cos(t), a * std::sin(t));
  const int B = m.joint("B", d + 0.3 * c, 0.9 * c);
  m.link(O, A, a);
  m.link(A, B, b);
  m.link(Q, B, c);
  m.crank(O, A, crank_deg);
  return m.d;
}

// Offset slider-crank: crank r about O, rod l to the slider S on the line y = e (along +x).
inline LinkageDescription slider_crank(double r, double l, double e, double crank_deg) {
  DescriptionBuilder m("slider-crank");
  const int O = m.ground("O", 0, 0);
  const double t = crank_deg * std::numbers::pi / 180.0;
  const int A = m.joint("A", r * std::cos(t), r * std::sin(t));
  const int S = m.joint("S", r + l, e);
  m.link(O, A, r);
  m.link(A, S, l);
  m.slider(S, 0.0, e, 0.0);
  m.crank(O, A, crank_deg);
  return m.d;
}

}  // namespace numlab::mechanisms::testing
