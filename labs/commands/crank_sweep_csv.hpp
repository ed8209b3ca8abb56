#pragma once
// The CSV of a crank sweep of the seeds' hand-coded linkages (numlab mechanism jansen|jansen10|
// mustang --format csv): one row per pose, docs/cli.md's columns (crank_deg, the model's angles,
// x_J and y_J of every joint, iterations, residual_inf, status), then one column of the linkage's
// own (the Jansen leg's foot_speed, the Mustang's condition).

#include <fmt/format.h>

#include <ostream>
#include <string_view>

namespace numlab::cli {

// `extra(pose)` gives the last column's value for each pose, printed to `extra_digits` significant digits.
template <typename Poses, typename Names, typename JointNames, typename Extra>
void print_crank_sweep_csv(std::ostream& out, const Poses& poses, const Names& angle_names, const JointNames& joint_names,
                           std::string_view extra_name, int extra_digits, Extra extra) {
  out << "crank_deg";
  for (const auto& name : angle_names) out << ',' << name;
  for (const auto& joint : joint_names) out << ",x_" << joint << ",y_" << joint;
  out << ",iterations,residual_inf,status," << extra_name << '\n';
  for (const auto& pose : poses) {
    out << fmt::format("{:.10g}", pose.crank_deg);
    for (double angle : pose.angles) out << fmt::format(",{:.17g}", angle);
    for (const auto& joint : pose.joints) out << fmt::format(",{:.17g},{:.17g}", joint.x(), joint.y());
    out << fmt::format(",{},{:.6g},{},{:.{}g}\n", pose.outcome.iterations, pose.outcome.residual_norm,
                       to_string(pose.outcome.status), extra(pose), extra_digits);
  }
}

}  // namespace numlab::cli
