#include "numlab/mechanisms/linkage/link_motion.hpp"

#include <cmath>
#include <limits>

namespace numlab::mechanisms {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string joined(const LinkageDescription& description, const std::vector<int>& joints) {
  std::string name;
  for (int j : joints) name += (name.empty() ? "" : "-") + description.joints[static_cast<std::size_t>(j)].name;
  return name;
}

}  // namespace

std::string link_name(const LinkageDescription& description, const LinkSpec& link) {
  return link.name.empty() ? joined(description, {link.first, link.second}) : link.name;
}

std::string body_column_name(const BodySpec& body, const LinkageDescription& description) {
  const bool defaulted = body.name.find(' ') != std::string::npos;  // "body K": a file's name has no space
  return defaulted ? joined(description, body.joints) : body.name;
}

std::vector<LinkLine> link_lines(const LinkageDescription& description) {
  std::vector<LinkLine> lines;
  for (const LinkSpec& link : description.links) {
    lines.push_back({link_name(description, link), link.first, link.second, false,
                     link.name.empty() ? link.place : link.name_place});
  }
  for (const BodySpec& body : description.bodies) {
    lines.push_back({body_column_name(body, description), body.joints[0], body.joints[1], true, body.place});
  }
  return lines;
}

std::vector<JointMotion> joint_motions(const LinkageModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& velocity,
                                       const Eigen::VectorXd& acceleration) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const auto& joints = model.description().joints;
  std::vector<JointMotion> out;
  out.reserve(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const int c = model.column_of(static_cast<int>(j));
    if (c < 0) {
      out.push_back({joints[j].position, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()});
      continue;
    }
    const auto pick = [&](const Eigen::VectorXd& v) {
      return v.size() == 0 ? Eigen::Vector2d(nan, nan) : Eigen::Vector2d(v(c), v(c + 1));
    };
    out.push_back({pick(q), pick(velocity), pick(acceleration)});
  }
  return out;
}

AngularMotion angular_motion(const JointMotion& from, const JointMotion& to) {
  const Eigen::Vector2d d = to.p - from.p, dv = to.v - from.v, da = to.a - from.a;
  const double r2 = d.squaredNorm();
  const double omega = cross(d, dv) / r2;
  const double alpha = cross(d, da) / r2 - 2.0 * d.dot(dv) * omega / r2;
  return {std::atan2(d.y(), d.x()), omega, alpha};
}

std::optional<LinkageOutput> find_output(const LinkageDescription& description, std::string_view name) {
  const auto lines = link_lines(description);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (lines[k].name == name) return LinkageOutput{lines[k].name, static_cast<int>(k), -1, -1, Eigen::Vector2d::UnitX(), -1, -1};
  }
  for (std::size_t s = 0; s < description.sliders.size(); ++s) {
    const SliderSpec& slider = description.sliders[s];
    if (description.joints[static_cast<std::size_t>(slider.joint)].name == name) {
      const double angle = slider.angle_deg * std::acos(-1.0) / 180.0;
      return LinkageOutput{std::string(name), -1, static_cast<int>(s), slider.joint,
                           {std::cos(angle), std::sin(angle)}, slider.line_from, slider.line_to};
    }
  }
  return std::nullopt;
}

std::string output_choices(const LinkageDescription& description) {
  std::string links, bodies, sliders;
  for (const LinkLine& line : link_lines(description)) {
    std::string& list = line.body ? bodies : links;
    list += (list.empty() ? "" : ", ") + line.name;
  }
  for (const SliderSpec& slider : description.sliders) {
    sliders += (sliders.empty() ? "" : ", ") + description.joints[static_cast<std::size_t>(slider.joint)].name;
  }
  std::string text = "links " + (links.empty() ? std::string("(none)") : links);
  if (!bodies.empty()) text += "; bodies " + bodies;
  if (!sliders.empty()) text += "; slider joints " + sliders;
  return text;
}

double output_rate(const LinkageOutput& output, const std::vector<LinkLine>& lines, const std::vector<JointMotion>& joints) {
  if (output.angle()) {
    const LinkLine& line = lines[static_cast<std::size_t>(output.line)];
    return angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]).omega;
  }
  const JointMotion& a = joints[static_cast<std::size_t>(output.joint)];
  if (output.line_from < 0) return output.direction.dot(a.v);
  const JointMotion& b = joints[static_cast<std::size_t>(output.line_from)];
  const JointMotion& c = joints[static_cast<std::size_t>(output.line_to)];
  const Eigen::Vector2d d = c.p - b.p, dd = c.v - b.v;
  const double length = d.norm();
  const Eigen::Vector2d w = d / length, dw = (dd - w * w.dot(dd)) / length;
  return (a.v - b.v).dot(w) + (a.p - b.p).dot(dw);
}

double mechanical_advantage(double velocity_ratio) {
  if (std::isnan(velocity_ratio)) return velocity_ratio;
  if (velocity_ratio == 0.0) return std::numeric_limits<double>::infinity();
  return 1.0 / velocity_ratio;
}

}  // namespace numlab::mechanisms
