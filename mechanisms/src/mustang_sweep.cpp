#include "numlab/mechanisms/mustang_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>


namespace numlab::mechanisms {

namespace {

constexpr double degrees = std::numbers::pi / 180.0;

double smallest_margin(const MustangLinkage& linkage, const MustangJoints& p) {
  double margin = linkage.loop_margin(0, p);
  for (int k = 1; k < MustangClosure::loops; ++k) margin = std::min(margin, linkage.loop_margin(k, p));
  return margin;
}

// Continuation in one direction from the start, through `targets` (in marching order).
class March {
 public:
  March(MustangPoseSolver& solver, const MustangSweepOptions& options, MustangSweep& sweep, const MustangAngles& start,
        double start_deg, int direction)
      : solver_(solver), options_(options), sweep_(sweep), x_(start), previous_(MustangAngles::Zero()), deg_(start_deg),
        direction_(direction) {}

  // Moves to target_deg; false (with the limit filled in) if the sweep had to stop before it.
  bool advance_to(double target_deg, MustangOutcome& last, MustangLimit& limit) {
    double step = std::min(options_.max_step_deg, std::abs(target_deg - deg_));
    if (step == 0.0) {  // already there: refine once, for the pose's own outcome
      last = solver_.solve(deg_ * degrees, x_);
      if (last.status == Status::converged) return true;
      limit = diagnose(deg_, last);
      return false;
    }
    while (deg_ != target_deg) {
      // 1. The next angle: one step on, or the target when it is that close.
      const bool last_step = std::abs(target_deg - deg_) <= step;
      const double next = last_step ? target_deg : deg_ + direction_ * step;
      // 2. Predict, correct, and check the branch; retry from the last pose if that fails.
      MustangOutcome outcome;
      MustangAngles trial;
      bool ok = try_solve(next, true, trial, outcome) || (has_previous_ && try_solve(next, false, trial, outcome));
      if (ok) {
        previous_ = x_;
        previous_step_ = next - deg_;
        has_previous_ = true;
        x_ = trial;
        deg_ = next;
        last = outcome;
        continue;  // keep the step: after a halving this is the next bisection point
      }
      // 3. Failed: halve the step (a bisection between the last pose and the failed angle),
      //    until the bracket is below the resolution.
      if (step <= options_.resolution_deg) {
        limit = diagnose(next, outcome);
        return false;
      }
      step *= 0.5;
      ++sweep_.step_halvings;
    }
    return true;
  }

  const MustangAngles& x() const { return x_; }
  double deg() const { return deg_; }

 private:
  bool try_solve(double next, bool predict, MustangAngles& trial, MustangOutcome& outcome) {
    trial = x_;
    if (predict && has_previous_) trial += (x_ - previous_) * ((next - deg_) / previous_step_);
    outcome = solver_.solve(next * degrees, trial);
    const bool converged = outcome.status == Status::converged && trial.allFinite();
    const bool ok = converged && MustangLinkage::on_seed_branch(linkage_.joints(next * degrees, trial));
    if (options_.trace) {
      const bool finite = trial.allFinite();
      sweep_.trace.push_back({next, next - deg_, outcome,
                              finite ? mustang_condition(next * degrees, trial) : std::nan(""),
                              finite ? smallest_margin(linkage_, linkage_.joints(next * degrees, trial)) : std::nan(""),
                              ok});
    }
    return ok;
  }

  // Past the last pose: does the linkage close `resolution` further on? If not, that is the limit.
  MustangLimit diagnose(double failed_deg, const MustangOutcome& outcome) const {
    MustangLimit limit;
    limit.reached = true;
    limit.last_assembled_deg = deg_;
    limit.failed_deg = failed_deg;
    limit.solver_loop = outcome.failed_loop;
    const MustangClosedForm beyond = linkage_.closed_form((deg_ + direction_ * options_.resolution_deg) * degrees);
    if (beyond.status == Status::cannot_assemble) {
      limit.status = Status::cannot_assemble;
      limit.loop = beyond.failed_loop;
    } else {
      limit.status = outcome.status == Status::converged ? Status::no_progress : outcome.status;  // left the branch
      limit.loop = outcome.failed_loop;
    }
    return limit;
  }

  MustangPoseSolver& solver_;
  const MustangSweepOptions& options_;
  MustangSweep& sweep_;
  MustangLinkage linkage_;
  MustangAngles x_, previous_;
  double deg_, previous_step_ = 0.0;
  bool has_previous_ = false;
  int direction_;
};

MustangPose checked_pose(const MustangLinkage& linkage, double deg, const MustangAngles& x, const MustangOutcome& outcome,
                         bool checks) {
  MustangPose pose;
  pose.crank_deg = deg;
  pose.angles = x;
  pose.outcome = outcome;
  pose.joints = linkage.joints(deg * degrees, x);
  if (!checks) return pose;
  pose.condition = mustang_condition(deg * degrees, x);
  pose.length_error = linkage.worst_length_error(pose.joints);
  pose.rigid_error = linkage.worst_rigid_body_error(pose.joints);
  pose.fixed_error = MustangLinkage::worst_fixed_point_error(pose.joints);
  const MustangClosedForm exact = linkage.closed_form(deg * degrees);
  pose.closed_form_distance = std::numeric_limits<double>::infinity();
  if (exact.status == Status::converged) {
    pose.closed_form_distance = 0.0;
    for (int j = 0; j < mustang_joint_count; ++j) {
      pose.closed_form_distance = std::max(pose.closed_form_distance, (pose.joints[j] - exact.joints[j]).norm());
    }
  }
  return pose;
}

}  // namespace

MustangSweep mustang_sweep(MustangPoseSolver& solver, double start_deg, double stop_deg, double step_deg,
                           const MustangSweepOptions& options) {
  if (!(step_deg != 0.0) || !std::isfinite(start_deg) || !std::isfinite(stop_deg) || !std::isfinite(step_deg) ||
      (stop_deg - start_deg) * step_deg < 0.0) {
    throw std::invalid_argument("sweep " + std::to_string(start_deg) + ":" + std::to_string(stop_deg) + ":" +
                                std::to_string(step_deg) + " does not step from its start towards its stop");
  }
  MustangSweep sweep;
  const MustangLinkage linkage;
  // 1. Seed 003's start at 45 deg.
  const MustangStart start = mustang_seed_start();
  if (start.status != Status::converged) {
    sweep.status = start.status;
    return sweep;
  }
  // The requested angles, split at the start: those above it marched upwards, the rest downwards.
  const int count = static_cast<int>(std::floor((stop_deg - start_deg) / step_deg + 1e-9)) + 1;
  std::vector<double> up, down;
  for (int i = 0; i < count; ++i) {
    const double angle = start_deg + i * step_deg;
    (angle >= MustangClosure::seed_crank_deg ? up : down).push_back(angle);
  }
  std::sort(up.begin(), up.end());
  std::sort(down.begin(), down.end(), std::greater<>());

  // 2. March each way; a limit ends that direction.
  std::vector<MustangPose> poses;
  MustangSweepOptions march_options = options;
  march_options.max_step_deg = std::min(options.max_step_deg, std::abs(step_deg));
  for (const int direction : {+1, -1}) {
    March march(solver, march_options, sweep, start.x, MustangClosure::seed_crank_deg, direction);
    MustangLimit& limit = direction > 0 ? sweep.upper : sweep.lower;
    for (const double target : direction > 0 ? up : down) {
      MustangOutcome outcome;
      if (!march.advance_to(target, outcome, limit)) break;
      poses.push_back(checked_pose(linkage, target, march.x(), outcome, options.checks));
    }
  }
  // 3. In the requested order, with the checks summed up.
  std::sort(poses.begin(), poses.end(), [&](const MustangPose& a, const MustangPose& b) {
    return step_deg > 0 ? a.crank_deg < b.crank_deg : a.crank_deg > b.crank_deg;
  });
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const MustangPose& pose = poses[i];
    sweep.worst_closed_form_distance = std::max(sweep.worst_closed_form_distance, pose.closed_form_distance);
    sweep.worst_length_error = std::max(sweep.worst_length_error, pose.length_error);
    sweep.worst_rigid_error = std::max(sweep.worst_rigid_error, pose.rigid_error);
    sweep.worst_fixed_error = std::max(sweep.worst_fixed_error, pose.fixed_error);
    if (i > 0) {
      const double dtheta = std::abs(pose.crank_deg - poses[i - 1].crank_deg) * degrees;
      sweep.worst_angle_rate =
          std::max(sweep.worst_angle_rate, (pose.angles - poses[i - 1].angles).lpNorm<Eigen::Infinity>() / dtheta);
    }
  }
  if (options.checks) sweep.branch_kept = sweep.worst_closed_form_distance <= 1e-6;
  sweep.poses = std::move(poses);
  for (const MustangLimit* limit : {&sweep.lower, &sweep.upper}) {
    if (limit->reached && sweep.status == Status::converged) sweep.status = limit->status;
  }
  return sweep;
}

}  // namespace numlab::mechanisms
