#include "linkage_page/builtin_page_data.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "linkage_page/builtin_csv.hpp"
#include "linkage_page/linkage_page_data.hpp"
#include "methods/data_dir.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"

namespace numlab::cli {

namespace {

using mechanisms::LinkageModel;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A built-in pose as the shipped file's model sees it: the crank angle, its joints by name, solved or not.
struct BuiltinPose {
  double crank_deg = 0.0;
  mechanisms::JointPositions joints;  // in the file's joint order
  bool solved = false;
};

// The file's joint order from the built-in's joint names (the same set; a missing one is a bug).
template <typename Joints, typename Names>
mechanisms::JointPositions in_file_order(const LinkageModel& model, const Joints& joints, const Names& names) {
  const auto& file_joints = model.description().joints;
  mechanisms::JointPositions out(file_joints.size());
  for (std::size_t j = 0; j < file_joints.size(); ++j) {
    std::size_t k = 0;
    while (k < names.size() && names[k] != file_joints[j].name) ++k;
    if (k == names.size()) throw std::logic_error("the shipped file's joint " + file_joints[j].name + " is not the built-in's");
    out[j] = joints[k];
  }
  return out;
}

// Every pose of a built-in sweep as the file's model sees it.
template <typename Poses, typename Names>
std::vector<BuiltinPose> builtin_poses(const LinkageModel& model, const Poses& poses, const Names& names) {
  std::vector<BuiltinPose> out;
  for (const auto& pose : poses) {
    out.push_back({pose.crank_deg, in_file_order(model, pose.joints, names), pose.outcome.status == Status::converged});
  }
  return out;
}

// Where a dyad of the file's model changes side between two poses the built-in solved: its two
// solutions met in between (a crossing of branches, J singular there), which the built-in's own
// sweep does not report. A mark at the middle of the two poses.
void add_crossing_marks(nlohmann::ordered_json& data, const LinkageModel& model, const mechanisms::LinkageSolver& solver,
                        const std::vector<BuiltinPose>& poses) {
  std::vector<int> before;
  double previous = 0.0;
  for (const BuiltinPose& pose : poses) {
    if (!pose.solved) {
      before.clear();
      continue;
    }
    const double t = model.driver_from_user(pose.crank_deg);
    const std::vector<int> side = solver.signature(model.unknowns(pose.joints), t);
    for (std::size_t b = 0; b < side.size() && b < before.size(); ++b) {
      if (!solver.blocks()[b].dyad() || side[b] == before[b] || side[b] == 0 || before[b] == 0) continue;
      data["marks"].push_back(
          {{"driver", 0.5 * (previous + pose.crank_deg)},
           {"kind", "crossing"},
           {"text", fmt::format("branch crossing between {:g} and {:g} deg: block {} ({}) changes side, its two "
                                "solutions meet in between (read from the file's model at the built-in's joints)",
                                previous, pose.crank_deg, b + 1, mechanisms::describe_block(model, solver.blocks()[b]))}});
    }
    before = side;
    previous = pose.crank_deg;
  }
}

// The columns the built-in's CSV lacks, from the file's model at its joints: vx_J, vy_J (zero at
// ground joints), mu_J per dyad block, and condition when the CSV has none; and the crossings.
void add_file_model_columns(nlohmann::ordered_json& data, const LinkageModel& model, const std::vector<BuiltinPose>& poses) {
  const mechanisms::LinkageSolver solver(model, {});
  const auto& joints = model.description().joints;
  std::vector<std::vector<double>> vx(joints.size()), vy(joints.size()), mu(solver.blocks().size());
  std::vector<double> condition;
  for (const BuiltinPose& pose : poses) {
    const Eigen::VectorXd q = model.unknowns(pose.joints);
    const double t = model.driver_from_user(pose.crank_deg);
    const Eigen::VectorXd v = pose.solved ? mechanisms::linkage_velocity(model, t, q) : Eigen::VectorXd();
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const int column = model.column_of(static_cast<int>(j));
      const bool known = column >= 0 && v.size() == model.unknown_count();
      vx[j].push_back(column < 0 ? (pose.solved ? 0.0 : nan) : known ? v(column) : nan);
      vy[j].push_back(column < 0 ? (pose.solved ? 0.0 : nan) : known ? v(column + 1) : nan);
    }
    const std::vector<double> angles = pose.solved ? solver.transmission_angles(q) : std::vector<double>(mu.size(), nan);
    for (std::size_t b = 0; b < mu.size(); ++b) mu[b].push_back(angles[b]);
    condition.push_back(pose.solved ? mechanisms::linkage_condition(model, t, q) : nan);
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    add_page_column(data, "vx_" + joints[j].name, vx[j]);
    add_page_column(data, "vy_" + joints[j].name, vy[j]);
  }
  for (std::size_t b = 0; b < mu.size(); ++b) {
    if (!solver.blocks()[b].dyad()) continue;
    std::string names;
    for (const int j : solver.blocks()[b].joints) names += (names.empty() ? "" : ", ") + joints[static_cast<std::size_t>(j)].name;
    add_page_column(data, "mu_" + names, mu[b]);
  }
  if (!data["columns"].contains("condition")) add_page_column(data, "condition", condition);
  add_crossing_marks(data, model, solver, poses);
}

LinkageModel shipped_model(const std::string& file) {
  return LinkageModel(mechanisms::read_linkage_description(models_dir() + "/" + file));
}

}  // namespace

nlohmann::ordered_json jansen_page_data(const std::string& name, mechanisms::JansenModel model,
                                        const mechanisms::JansenSweep& sweep, const std::string& origin) {
  const LinkageModel drawing = shipped_model("jansen.toml");
  std::ostringstream csv;
  print_jansen_csv(csv, model, sweep);
  const bool eight = model == mechanisms::JansenModel::eight_equations;
  PageSource source{drawing, name, eight ? "Jansen leg, seed 000's 8 equations" : "Jansen leg, seed 001's 10 equations",
                    csv.str(), std::nullopt,
                    {"The built-in model's numbers (" + origin + "); the velocities, the "
                     "transmission angles and kappa(J) are those of jansen.toml's joint-coordinate model (12 "
                     "unknowns) at the built-in's joints. Velocities are per radian of crank."},
                    {}};
  nlohmann::ordered_json data = linkage_page_data(source);
  add_file_model_columns(data, drawing, builtin_poses(drawing, sweep.poses, mechanisms::jansen_joint_names));
  return data;
}

nlohmann::ordered_json mustang_page_data(const mechanisms::MustangSweep& sweep, double start_deg, double stop_deg,
                                         const std::string& origin) {
  const LinkageModel drawing = shipped_model("mustang.toml");
  std::ostringstream csv;
  print_mustang_csv(csv, sweep);
  std::vector<PageMark> marks;
  for (const auto* limit : {&sweep.lower, &sweep.upper}) {
    if (!limit->reached || limit->status != Status::cannot_assemble) continue;
    marks.push_back({limit->last_assembled_deg, "limit",
                     fmt::format("{} assembly limit: {:.4f} deg assembles, {:.4f} deg does not (loop {} cannot close)",
                                 limit == &sweep.lower ? "lower" : "upper", limit->last_assembled_deg, limit->failed_deg,
                                 limit->loop)});
  }
  PageSource source{drawing, "mustang", "Ford Mustang roof linkage (seed 003)", csv.str(), std::nullopt,
                    {fmt::format("The sweep asked for {:g} .. {:g} deg; the built-in keeps only the poses that "
                                 "assembled, so the slider runs between its assembly limits.", start_deg, stop_deg),
                     "The built-in model's numbers (" + origin + "; kappa(J) of its 8 "
                     "equations); the velocities and transmission angles are those of mustang.toml's "
                     "joint-coordinate model (20 unknowns) at the built-in's joints, per radian of input."},
                    std::move(marks)};
  nlohmann::ordered_json data = linkage_page_data(source);
  add_file_model_columns(data, drawing, builtin_poses(drawing, sweep.poses, mechanisms::mustang_joint_names));
  return data;
}

}  // namespace numlab::cli
