#include "scenes/foot_path.hpp"

#include <numbers>
#include <stdexcept>

#include "numlab/mechanisms/jansen_leg.hpp"

namespace numlab::cli {

fitting::SplitPath jansen_foot_arcs() {
  const mechanisms::JansenLeg leg;
  constexpr int poses = 360;
  Eigen::VectorXd x(poses), y(poses);
  for (int degree = 0; degree < poses; ++degree) {
    const auto joints = leg.closed_form_joints(degree * std::numbers::pi / 180.0);
    if (!joints) throw std::runtime_error("the Jansen leg does not assemble at crank " + std::to_string(degree));
    const auto& foot = (*joints)[static_cast<std::size_t>(mechanisms::JansenJoint::F)];
    x(degree) = foot.x();
    y(degree) = foot.y();
  }
  return fitting::split_at_extreme_x(x, y);
}

fitting::PathArc jansen_foot_arc(const std::string& which) {
  if (which == "upper") return jansen_foot_arcs().upper;
  if (which == "lower") return jansen_foot_arcs().lower;
  throw std::invalid_argument("--foot-path '" + which + "': expected upper or lower");
}

}  // namespace numlab::cli
