#include "numlab/mechanisms/mustang_linkage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/mechanisms/plane_angles.hpp"

namespace numlab::mechanisms {

namespace {

constexpr double pi = std::numbers::pi;
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

const Eigen::Vector2d fixed_P0(std::sqrt(0.5), 0.0), fixed_P1(0.0, std::sqrt(0.5)), fixed_P2(0.0, 1.0 + std::sqrt(0.5));

// P4, P6, P7: the input link 2-4-6-7, rigid, at theta.
void place_input_link(const MustangLengths& L, double theta, MustangJoints& p) {
  p[0] = fixed_P0;
  p[1] = fixed_P1;
  p[2] = fixed_P2;
  p[4] = p[2] + L.l2_4 * unit(theta);
  p[6] = p[4] + L.l4_6 * unit(theta + 2.0 * L.bend);
  p[7] = p[6] + L.l6_7 * unit(theta + L.bend);
}

// P8, P9: link 5-6-8-9 follows 5->6, which points along u(pi - C).
void place_second_link(const MustangLengths& L, double direction5_6, MustangJoints& p) {
  p[8] = p[6] + L.l6_8 * unit(direction5_6 + L.bend);
  p[9] = p[8] + L.l8_9 * unit(direction5_6 - L.bend);
}

// P12 on link 9-11-12, which turns 40 degrees at 11 (see the header).
void place_third_link(const MustangLengths& L, double direction9_11, MustangJoints& p) {
  p[12] = p[11] + L.l11_12 * unit(direction9_11 - 2.0 * L.bend);
}

}  // namespace

MustangLinkage::MustangLinkage(MustangLengths lengths) : lengths_(lengths) {
  const MustangLengths& L = lengths_;
  links_ = {{0, 1, L.l0_1},   {1, 2, L.l1_2},   {1, 3, L.l1_3},    {3, 4, L.l3_4},     {0, 5, L.l0_5},  {2, 4, L.l2_4},
            {4, 6, L.l4_6},   {6, 7, L.l6_7},   {5, 6, L.l5_6},    {6, 8, L.l6_8},     {8, 9, L.l8_9},  {7, 10, L.l7_10},
            {10, 8, L.l10_8}, {10, 11, L.l10_11}, {9, 11, L.l9_11}, {11, 12, L.l11_12}};
  // The rigid bodies (the ground and the three bent major links), their shapes read off one pose
  // built from their definitions alone.
  bodies_ = {{0, 1, 2}, {2, 4, 6, 7}, {5, 6, 8, 9}, {9, 11, 12}};
  MustangJoints shape;
  shape.fill(Eigen::Vector2d::Zero());
  place_input_link(L, 0.0, shape);
  shape[5] = shape[6] - L.l5_6 * unit(0.0);
  place_second_link(L, 0.0, shape);
  shape[11] = shape[9] + L.l9_11 * unit(0.0);
  place_third_link(L, 0.0, shape);
  reference_.assign(bodies_.size(), shape);
}

MustangJoints MustangLinkage::joints(double theta, const MustangAngles& x) const {
  const MustangLengths& L = lengths_;
  const double A = x(0), C = x(2), D = x(3), F = x(5), G = x(6), H = x(7);
  MustangJoints p;
  p.fill(Eigen::Vector2d::Zero());
  place_input_link(L, theta, p);
  p[3] = p[1] + L.l1_3 * unit(A);       // loop 1: 1 -> 3 at A
  p[5] = p[0] + L.l0_5 * unit(D);       // loop 2: 0 -> 5 at D
  place_second_link(L, pi - C, p);      // 5 -> 6 at pi - C
  p[10] = p[8] + L.l10_8 * unit(F);     // loop 3: 8 -> 10 at F
  p[11] = p[10] + L.l10_11 * unit(pi - G);  // loop 4: 10 -> 11 at pi - G
  place_third_link(L, pi - H, p);       // 9 -> 11 at pi - H
  return p;
}

MustangClosedForm MustangLinkage::closed_form(double theta) const {
  const MustangLengths& L = lengths_;
  MustangClosedForm result;
  result.joints.fill(Eigen::Vector2d::Zero());
  MustangJoints& p = result.joints;
  auto cannot_close = [&](int loop) {
    result.status = Status::cannot_assemble;
    result.failed_loop = loop;
    return result;
  };
  // 1. The input link is placed by theta alone.
  place_input_link(L, theta, p);
  // 2. Loop 1: P3 on circle(P1, |1 3|) and circle(P4, |3 4|).
  const auto P3 = circle_intersection(p[1], L.l1_3, p[4], L.l3_4, side_P3);
  if (!P3) return cannot_close(1);
  p[3] = *P3;
  // 3. Loop 2: P5 on circle(P0, |0 5|) and circle(P6, |5 6|); then link 5-6-8-9 follows.
  const auto P5 = circle_intersection(p[0], L.l0_5, p[6], L.l5_6, side_P5);
  if (!P5) return cannot_close(2);
  p[5] = *P5;
  place_second_link(L, direction(p[5], p[6]), p);
  // 4. Loop 3: P10 on circle(P8, |10 8|) and circle(P7, |7 10|).
  const auto P10 = circle_intersection(p[8], L.l10_8, p[7], L.l7_10, side_P10);
  if (!P10) return cannot_close(3);
  p[10] = *P10;
  // 5. Loop 4, the open kite: P11 on circle(P10, |10 11|) and circle(P9, |9 11|), on the other
  //    side of the line 10 -> 9 from P8.
  const auto P11 = circle_intersection(p[10], L.l10_11, p[9], L.l9_11, -side_of(p[10], p[9], p[8]));
  if (!P11) return cannot_close(4);
  p[11] = *P11;
  place_third_link(L, direction(p[9], p[11]), p);
  return result;
}

MustangAngles MustangLinkage::angles_of(const MustangJoints& p, const MustangAngles& near) {
  MustangAngles x;
  x << direction(p[1], p[3]), direction(p[3], p[4]), pi - direction(p[5], p[6]), direction(p[0], p[5]),
      pi - direction(p[7], p[10]), direction(p[8], p[10]), pi - direction(p[10], p[11]), pi - direction(p[9], p[11]);
  constexpr double turn = 2.0 * pi;
  for (int k = 0; k < 8; ++k) x(k) += turn * std::round((near(k) - x(k)) / turn);
  return x;
}

bool MustangLinkage::on_seed_branch(const MustangJoints& p) {
  // Loops 1-3: each dyad on its side of the line through its circles' centres.
  if (side_of(p[1], p[4], p[3]) != side_P3 || side_of(p[0], p[6], p[5]) != side_P5 || side_of(p[8], p[7], p[10]) != side_P10) {
    return false;
  }
  // Loop 4: the open kite, P11 = P8 mirrored in the line 9-10.
  const Eigen::Vector2d along = (p[10] - p[9]).normalized(), from9 = p[8] - p[9];
  const Eigen::Vector2d mirrored = p[9] + 2.0 * from9.dot(along) * along - from9;
  return (p[11] - mirrored).norm() < (p[11] - p[8]).norm();
}

double MustangLinkage::loop_margin(int k, const MustangJoints& p) const {
  const MustangLengths& L = lengths_;
  struct Dyad {
    int centre1, centre2;
    double r1, r2;
  };
  const Dyad dyads[4] = {{1, 4, L.l1_3, L.l3_4}, {0, 6, L.l0_5, L.l5_6}, {8, 7, L.l10_8, L.l7_10}, {10, 9, L.l10_11, L.l9_11}};
  const Dyad& d = dyads[k];
  const double distance = (p[d.centre2] - p[d.centre1]).norm();
  return std::min(distance - std::abs(d.r1 - d.r2), d.r1 + d.r2 - distance);
}

double MustangLinkage::worst_length_error(const MustangJoints& p) const {
  double worst = 0.0;
  for (const MustangLink& link : links_) {
    worst = std::max(worst, std::abs((p[link.to] - p[link.from]).norm() - link.length));
  }
  return worst;
}

double MustangLinkage::worst_rigid_body_error(const MustangJoints& p) const {
  double worst = 0.0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto& body = bodies_[b];
    const MustangJoints& ref = reference_[b];
    for (std::size_t i = 0; i < body.size(); ++i) {
      for (std::size_t j = i + 1; j < body.size(); ++j) {
        // Every pair keeps its distance ...
        const int a = body[i], c = body[j];
        worst = std::max(worst, std::abs((p[c] - p[a]).norm() - (ref[c] - ref[a]).norm()));
        // ... and every triple its signed area (a mirror image would flip the sign).
        for (std::size_t k = j + 1; k < body.size(); ++k) {
          const int e = body[k];
          worst = std::max(worst, std::abs(cross(p[c] - p[a], p[e] - p[a]) - cross(ref[c] - ref[a], ref[e] - ref[a])));
        }
      }
    }
  }
  return worst;
}

double MustangLinkage::worst_fixed_point_error(const MustangJoints& p) {
  return std::max({(p[0] - fixed_P0).norm(), (p[1] - fixed_P1).norm(), (p[2] - fixed_P2).norm()});
}

}  // namespace numlab::mechanisms
