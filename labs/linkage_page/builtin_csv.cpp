#include "linkage_page/builtin_csv.hpp"

#include <limits>
#include <numbers>

#include "commands/crank_sweep_csv.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"

namespace numlab::cli {

using mechanisms::JansenModel;

double jansen_foot_speed(JansenModel model, const mechanisms::JansenPose& pose) {
  // The 10-equation model's joints are the same: its 8 angles are read off them.
  const mechanisms::JansenLeg leg;
  const Eigen::VectorXd eight =
      model == JansenModel::eight_equations
          ? pose.angles
          : mechanisms::jansen_angles_of(JansenModel::eight_equations, pose.joints,
                                         Eigen::VectorXd(mechanisms::JansenClosure::seed_estimates()));
  const auto rates = leg.rates(pose.crank_deg * std::numbers::pi / 180.0, mechanisms::JansenAngles(eight));
  return rates.status == Status::converged ? rates.foot_speed : std::numeric_limits<double>::quiet_NaN();
}

void print_jansen_csv(std::ostream& out, JansenModel model, const mechanisms::JansenSweep& sweep) {
  print_crank_sweep_csv(out, sweep.poses, mechanisms::jansen_angle_names(model), mechanisms::jansen_joint_names,
                        "foot_speed", 10, [&](const mechanisms::JansenPose& pose) { return jansen_foot_speed(model, pose); });
}

void print_mustang_csv(std::ostream& out, const mechanisms::MustangSweep& sweep) {
  print_crank_sweep_csv(out, sweep.poses, mechanisms::mustang_angle_names, mechanisms::mustang_joint_names, "condition", 6,
                        [](const mechanisms::MustangPose& pose) { return pose.condition; });
}

}  // namespace numlab::cli
