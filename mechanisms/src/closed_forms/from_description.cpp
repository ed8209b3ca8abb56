// The closed forms' numbers read from the shipped files (closed_forms/from_description.hpp).

#include "numlab/mechanisms/closed_forms/from_description.hpp"

#include <stdexcept>
#include <string>

namespace numlab::mechanisms::closed_forms {

namespace {

Eigen::Vector2d position(const LinkageDescription& d, const std::string& name) {
  const int index = d.joint_index(name);
  if (index < 0) throw std::invalid_argument(d.file + ": no joint " + name);
  return d.joints[static_cast<std::size_t>(index)].position;
}

double length(const LinkageDescription& d, const std::string& first, const std::string& second) {
  const int a = d.joint_index(first), b = d.joint_index(second);
  for (const LinkSpec& link : d.links) {
    if ((link.first == a && link.second == b) || (link.first == b && link.second == a)) return link.length;
  }
  throw std::invalid_argument(d.file + ": no link " + first + "-" + second);
}

// The body holding joint `name`, and that joint's local point.
const BodySpec& body_with(const LinkageDescription& d, const std::string& name) {
  const int index = d.joint_index(name);
  for (const BodySpec& body : d.bodies) {
    for (const int joint : body.joints) {
      if (joint == index) return body;
    }
  }
  throw std::invalid_argument(d.file + ": no body holds " + name);
}

Eigen::Vector2d local(const LinkageDescription& d, const BodySpec& body, const std::string& name) {
  const int index = d.joint_index(name);
  for (std::size_t k = 0; k < body.joints.size(); ++k) {
    if (body.joints[k] == index) return body.local[k];
  }
  throw std::invalid_argument(d.file + ": the body does not hold " + name);
}

int side_of(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& point) {
  return cross(to - from, point - from) >= 0.0 ? 1 : -1;
}

}  // namespace

InvertedSliderCrank inverted_slider_crank_of(const LinkageDescription& d) {
  return {position(d, "O"), position(d, "B"), length(d, "O", "A"), length(d, "B", "C")};
}

Whitworth whitworth_of(const LinkageDescription& d) {
  const int ram = d.joint_index("C");
  for (const SliderSpec& slider : d.sliders) {
    if (slider.joint != ram) continue;
    if (slider.on_link() || slider.angle_deg != 0.0) throw std::invalid_argument(d.file + ": C's slider is not along +x");
    const Eigen::Vector2d B = position(d, "B"), C = position(d, "C");
    return {position(d, "O2"), position(d, "O4"), length(d, "O2", "A"), length(d, "O4", "B"), length(d, "B", "C"),
            slider.through.y(), C.x() >= B.x() ? 1 : -1};
  }
  throw std::invalid_argument(d.file + ": no slider holds C");
}

HydraulicBoom hydraulic_boom_of(const LinkageDescription& d) {
  const BodySpec& boom = body_with(d, "T");
  const Eigen::Vector2d o = local(d, boom, "O"), b = local(d, boom, "B") - o, t = local(d, boom, "T") - o;
  const Eigen::Vector2d O = position(d, "O"), P = position(d, "P");
  return {O, P, b.norm(), t.norm(), std::atan2(cross(b, t), b.dot(t)), side_of(O, P, position(d, "B"))};
}

WattLinkage watt_linkage_of(const LinkageDescription& d) {
  const BodySpec& coupler = body_with(d, "M");
  const Eigen::Vector2d b = local(d, coupler, "B"), m = local(d, coupler, "M"), c = local(d, coupler, "C");
  const Eigen::Vector2d O2 = position(d, "O2");
  return {position(d, "O1"), O2, length(d, "O1", "B"), (c - b).norm(), length(d, "O2", "C"),
          (m - b).dot(c - b) / (c - b).squaredNorm(), side_of(position(d, "B"), O2, position(d, "C"))};
}

}  // namespace numlab::mechanisms::closed_forms
