#include "bench/bench_linkage_scaling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/progress_line.hpp"
#include "bench/timing.hpp"
#include "numlab/mechanisms/linkage/dyad_chain.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {
constexpr double scaling_start = 60.0, scaling_stop = 69.0, scaling_step = 1.0;
constexpr int scaling_poses = 10;
}  // namespace

std::vector<LinkageScalingRow> bench_linkage_scaling(bool quick) {
  std::vector<LinkageScalingRow> rows;
  for (const int joints : {10, 100, 250, 500, 1000}) {
    show_progress(fmt::format("bench linkage-scaling: {} joints", joints));
    const mechanisms::LinkageModel model(
        mechanisms::parse_linkage_description(mechanisms::dyad_chain_description(joints), fmt::format("chain-{}.toml", joints)));
    const mechanisms::LinkageSolver solver(model, {});
    const auto sweep = [&] { return mechanisms::linkage_sweep(solver, scaling_start, scaling_stop, scaling_step); };
    const mechanisms::LinkageSweep checked = sweep();
    double worst = 0.0;
    for (const auto& pose : checked.poses) worst = std::max(worst, pose.condition);
    const TimingPlan plan = quick || joints == 1000 ? TimingPlan{quick ? 1 : 3, 3, 0.0} : TimingPlan{5, 100, 0.3};
    const double seconds = median_time(sweep, plan);
    rows.push_back({joints, model.unknown_count(), seconds, seconds / scaling_poses, checked.status,
                    checked.closed_form_verified, worst});
  }
  show_progress("");
  return rows;
}

int run_linkage_scaling_bench(const BenchOptions& common, bool quick) {
  const std::vector<LinkageScalingRow> rows = bench_linkage_scaling(quick);
  const double base = rows.front().per_pose_s;
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "linkage-scaling"}, {"poses", scaling_poses}, {"rows", nlohmann::ordered_json::array()}};
    for (const auto& row : rows) {
      out["rows"].push_back({{"joints", row.joints},
                             {"unknowns", row.unknowns},
                             {"sweep_s", row.sweep_s},
                             {"per_pose_s", row.per_pose_s},
                             {"ratio_to_10_joints", row.per_pose_s / base},
                             {"status", std::string(to_string(row.status))},
                             {"closed_form_verified", row.verified},
                             {"worst_condition", row.worst_condition}});
    }
    std::cout << out.dump(2) << '\n';
  } else if (common.format == Format::csv) {
    std::cout << "joints,unknowns,sweep_s,per_pose_s,ratio_to_10_joints,status,closed_form_verified,worst_condition\n";
    for (const auto& row : rows) {
      std::cout << fmt::format("{},{},{:.6g},{:.6g},{:.4g},{},{},{:.4g}\n", row.joints, row.unknowns, row.sweep_s,
                               row.per_pose_s, row.per_pose_s / base, to_string(row.status), row.verified ? "true" : "false",
                               row.worst_condition);
    }
  } else {
    std::cout << "Median time per pose of a 10-pose sweep (crank 60..69 deg, full Newton, every pose's analysis)\n"
              << "of a chain of dyads: a four-bar carrying a strip of triangles. Ratio: to 10 joints; linear growth\n"
              << "is the ratio of the joints. kappa(J): kappa_2 up to 100 unknowns, kappa_1 (estimated) beyond.\n\n";
    Table table({"joints", "unknowns", "per pose", "ratio", "sweep", "status", "verified", "worst kappa(J)"});
    for (const auto& row : rows) {
      table.add_row({std::to_string(row.joints), std::to_string(row.unknowns), fmt::format("{:.3g} s", row.per_pose_s),
                     fmt::format("{:.1f}x", row.per_pose_s / base), fmt::format("{:.3g} s", row.sweep_s),
                     std::string(to_string(row.status)), row.verified ? "yes" : "NO", fmt::format("{:.3g}", row.worst_condition)});
    }
    table.print(std::cout);
  }
  return rows.back().status == Status::converged ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
