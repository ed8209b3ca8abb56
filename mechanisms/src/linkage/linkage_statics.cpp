// The driving torque and the reactions by Lagrange multipliers (linkage_statics.hpp, steps 1-4).
#include "numlab/mechanisms/linkage/linkage_statics.hpp"

#include <cmath>
#include <limits>

#include "linkage_crossings.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"

namespace numlab::mechanisms {

namespace {

Eigen::Vector2d joint_position(const LinkageModel& model, const Eigen::VectorXd& q, int joint) {
  const int column = model.column_of(joint);
  return column < 0 ? model.description().joints[static_cast<std::size_t>(joint)].position
                    : Eigen::Vector2d(q(column), q(column + 1));
}

Eigen::Vector2d normal_of(const Eigen::Vector2d& d) { return {-d.y(), d.x()}; }

}  // namespace

std::vector<StaticsSupport> statics_supports(const LinkageDescription& description) {
  std::vector<StaticsSupport> supports;
  for (std::size_t j = 0; j < description.joints.size(); ++j) {
    if (description.joints[j].ground) supports.push_back({description.joints[j].name, static_cast<int>(j), -1});
  }
  for (std::size_t s = 0; s < description.sliders.size(); ++s) {
    if (description.sliders[s].on_link()) continue;  // its guide is a moving link: an internal force
    const int joint = description.sliders[s].joint;
    supports.push_back({description.joints[static_cast<std::size_t>(joint)].name, joint, static_cast<int>(s)});
  }
  return supports;
}

std::string_view to_string(StaticsStatus status) {
  switch (status) {
    case StaticsStatus::equilibrium: return "equilibrium";
    case StaticsStatus::singular: return "singular";
    case StaticsStatus::no_pose: return "no_pose";
  }
  return "no_pose";
}

void applied_joint_forces(const LinkageModel& model, const Eigen::VectorXd& q, std::vector<Eigen::Vector2d>& forces) {
  const LinkageDescription& description = model.description();
  for (Eigen::Vector2d& f : forces) f.setZero();
  for (const LoadSpec& load : description.loads) {
    switch (load.kind) {
      case LoadKind::force:
        forces[static_cast<std::size_t>(load.joint)] += load.force;
        break;
      case LoadKind::mass:
        forces[static_cast<std::size_t>(load.joint)].y() -= load.mass * description.gravity;
        break;
      case LoadKind::torque: {
        // The couple: T perp(d) / |d|^2 at `to`, its opposite at `from`; its moment is d x that = T.
        int from = -1, to = -1;
        const int links = static_cast<int>(description.links.size());
        if (load.line < links) {
          from = description.links[static_cast<std::size_t>(load.line)].first;
          to = description.links[static_cast<std::size_t>(load.line)].second;
        } else {
          const BodySpec& body = description.bodies[static_cast<std::size_t>(load.line - links)];
          from = body.joints[0];
          to = body.joints[1];
        }
        const Eigen::Vector2d d = joint_position(model, q, to) - joint_position(model, q, from);
        const Eigen::Vector2d f = load.torque * normal_of(d) / d.squaredNorm();
        forces[static_cast<std::size_t>(to)] += f;
        forces[static_cast<std::size_t>(from)] -= f;
        break;
      }
    }
  }
}

LinkageStaticsSolver::LinkageStaticsSolver(const LinkageModel& model)
    : model_(model),
      supports_(statics_supports(model.description())),
      J_(model.equation_count(), model.unknown_count()),
      lu_(model.unknown_count()),
      Q_(model.unknown_count()),
      lambda_(model.unknown_count()),
      phi_t_(model.equation_count()),
      applied_(model.description().joints.size()),
      constraint_(model.description().joints.size()) {
  for (const StaticsSupport& support : supports_) {
    int row = -1;
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k < model.constraints().size(); ++k) {
      const Constraint& c = model.constraints()[k];
      if (support.slider >= 0 && c.kind == ConstraintKind::slider_line && c.joints[0] == support.joint) {
        row = model.first_row(static_cast<int>(k));
        normal = normal_of(c.direction);  // d (u x (p - P)) / d p
      }
    }
    guide_rows_.push_back(row);
    guide_normals_.push_back(normal);
  }
  result_.reactions.assign(supports_.size(), Eigen::Vector2d::Zero());
}

const LinkageStatics& LinkageStaticsSolver::solve(const LinkagePose& pose) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto unbounded = [&](StaticsStatus status) -> const LinkageStatics& {
    result_.status = status;
    result_.driver = status == StaticsStatus::singular ? inf : std::numeric_limits<double>::quiet_NaN();
    result_.second_driver = model_.has_second_driver() ? result_.driver : 0.0;
    for (Eigen::Vector2d& r : result_.reactions) r.setConstant(result_.driver);
    return result_;
  };
  if (pose.outcome.status != Status::converged || pose.q.size() != model_.unknown_count() || !pose.q.allFinite()) {
    return unbounded(StaticsStatus::no_pose);
  }
  if (!(pose.condition <= detail::singular_condition) || pose.kinematics_by_differences) {
    return unbounded(StaticsStatus::singular);
  }
  const double t = model_.driver_from_user(pose.driver);
  // 1. The loads as forces on the joints; Q is the moving joints' part.
  applied_joint_forces(model_, pose.q, applied_);
  for (std::size_t j = 0; j < applied_.size(); ++j) {
    const int column = model_.column_of(static_cast<int>(j));
    if (column >= 0) Q_.segment<2>(column) = applied_[j];
  }
  // 2. J^T lambda = Q, by J^T's LU.
  model_.jacobian(pose.q, t, J_);
  lu_.compute(J_.transpose());
  lambda_ = lu_.solve(Q_);
  if (!lambda_.allFinite()) return unbounded(StaticsStatus::singular);
  // 3. The driver's load: lambda . Phi_t.
  model_.driver_derivative(pose.q, t, phi_t_);
  result_.driver = lambda_.dot(phi_t_);
  if (model_.has_second_driver()) {  // the second driver's, from its own column of d Phi / d (drivers)
    model_.second_driver_derivative(pose.second_driver, phi_t_);
    result_.second_driver = lambda_.dot(phi_t_);
  }
  // 4. The reactions.
  model_.multiplier_forces(pose.q, t, lambda_, constraint_);
  for (std::size_t s = 0; s < supports_.size(); ++s) {
    const StaticsSupport& support = supports_[s];
    const int row = guide_rows_[s];
    if (support.slider < 0) {
      result_.reactions[s] = constraint_[static_cast<std::size_t>(support.joint)] - applied_[static_cast<std::size_t>(support.joint)];
    } else {
      result_.reactions[s] = row < 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(-lambda_(row) * guide_normals_[s]);
    }
  }
  result_.status = StaticsStatus::equilibrium;
  return result_;
}

}  // namespace numlab::mechanisms
