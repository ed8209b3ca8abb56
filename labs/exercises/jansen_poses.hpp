#pragma once
// The Jansen leg's exact poses for the exercises: seed 000's 8 angles from the closed form (circle
// intersections, jansen_leg.hpp) on the seed's branch, and what checks say about them.

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exercises/reply_fields.hpp"
#include "exercises/variant.hpp"
#include "exercises/variant_lengths.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"

namespace numlab::exercises {

// theta1 ... theta8 of the closed-form pose of `leg` at `crank_angle` (radians), on seed 000's
// branch; std::logic_error when the leg does not assemble there.
mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle, const mechanisms::JansenLeg& leg = mechanisms::JansenLeg());

// theta3 ... theta12 of seed 001's 10-equation model at the same closed-form pose, each within pi
// of the model's start (jansen_seed_estimates).
Eigen::VectorXd jansen10_closed_form_angles(double crank_angle, const mechanisms::JansenLeg& leg = mechanisms::JansenLeg());

// The sum of the links of the 8-equation closure (15 + 50 + ... + 36.7): f's scale in messages.
double jansen_links_sum(const mechanisms::JansenLengths& L = {});

// The Jansen leg a battery checks: seed 000's lengths without a variant; with one, every length
// (crank, l1 ... l8, a, b, and with the foot l9, l10) within +-3% of seed 000's (variant_lengths),
// drawn again until the closed form assembles on the seed's branch at every quarter degree of the
// crank cycle (no dyad opens, the rigid triangles keep their orientation) and `valid` accepts it.
struct JansenVariant {
  mechanisms::JansenLengths links;
  mechanisms::JansenFootLengths foot;
  bool varied = false;  // the requests carry `lengths` only then
  bool with_foot = false;
  mechanisms::JansenLeg leg() const { return mechanisms::JansenLeg(links, foot); }
  LinkLengths named() const;
  // Adds `lengths` to a request when varied.
  void add_to(nlohmann::json& request) const;
};
JansenVariant jansen_variant(const Variant& variant, bool with_foot,
                             const std::function<bool(const mechanisms::JansenLeg&)>& valid = {});
// jansen_variant whose leg assembles at every pose `poses(variant, leg)` builds (the closed form
// throws std::logic_error where it does not).
template <typename Poses>
JansenVariant jansen_variant_for_poses(const Variant& variant, bool with_foot, Poses poses) {
  return jansen_variant(variant, with_foot, [&](const mechanisms::JansenLeg& leg) {
    try {
      poses(variant, leg);
      return true;
    } catch (const std::logic_error&) {
      return false;
    }
  });
}
// A Jacobian exercise's battery: the leg's lengths (a variant's, or seed 000's) and the poses
// `poses(variant, leg)` builds on that leg.
template <typename Pose>
struct JacobianBattery {
  JansenVariant lengths;
  std::vector<Pose> list;
};
template <typename Pose, typename Poses>
JacobianBattery<Pose> jacobian_battery(const Variant& variant, bool with_foot, Poses poses) {
  JacobianBattery<Pose> battery;
  battery.lengths = jansen_variant_for_poses(variant, with_foot, poses);
  battery.list = poses(variant, battery.lengths.leg());
  return battery;
}
// One pose's request, {crank_angle, theta}, with the leg's `lengths` when they are varied.
template <typename Pose>
nlohmann::json jacobian_request(const Pose& pose, const JansenVariant& lengths) {
  nlohmann::json request = {{"crank_angle", pose.crank_angle}, {"theta", to_json(Eigen::VectorXd(pose.theta))}};
  lengths.add_to(request);
  return request;
}
// A wrong_link detector's evidence: under a varied leg, the student's f equals `seed_f` (numlab's f
// with seed 000's lengths) to `tolerance`. Nothing otherwise.
std::optional<std::string> jansen_seed_lengths_used(const Eigen::VectorXd& f, const Eigen::VectorXd& seed_f,
                                                    const JansenVariant& lengths, double tolerance);
// TASK.md's words on a variant's lengths ("" when not varied).
std::string jansen_lengths_task_text(const JansenVariant& lengths);

// "theta3" for index 2.
std::string jansen_angle_name(int index);

inline constexpr double degrees = 3.14159265358979323846 / 180.0;

// The Jacobian exercises' poses ({crank_angle, theta}): `start`, the closed-form pose at 0, 90, 200
// and 300 degrees, and two poses away from any root (where f is large, so every term of every row
// counts): the closed form at 1.0 rad plus `offset` and at 4.0 rad minus twice it. With a variant,
// one of the four crank angles is drawn in each quarter turn, and the two others and the offset
// (entries in [-0.5, 0.5)) are drawn too.
template <typename Pose, typename ClosedForm>
std::vector<Pose> jacobian_poses(const Variant& variant, Pose start, decltype(Pose::theta) offset,
                                 ClosedForm closed_form) {
  std::vector<Pose> list = {std::move(start)};
  Variant::Stream stream = variant.stream(1);
  for (double deg : {0.0, 90.0, 200.0, 300.0}) {
    if (variant.active()) deg = std::floor(deg / 90.0) * 90.0 + stream.uniform(0.0, 90.0);
    list.push_back({deg * degrees, closed_form(deg * degrees)});
  }
  double first = 1.0, second = 4.0;
  if (variant.active()) {
    for (Eigen::Index k = 0; k < offset.size(); ++k) offset(k) = stream.uniform(-0.5, 0.5);
    first = stream.uniform(0.0, 3.0);
    second = stream.uniform(3.2, 6.2);
  }
  list.push_back({first, closed_form(first) + offset});
  list.push_back({second, closed_form(second) - 2.0 * offset});
  return list;
}

}  // namespace numlab::exercises
