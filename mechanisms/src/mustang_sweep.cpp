#include "numlab/mechanisms/mustang_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numlab/mechanisms/closed_form_bound.hpp"
#include "numlab/mechanisms/crank_angle.hpp"

namespace numlab::mechanisms {

namespace {


double smallest_margin(const MustangLinkage& linkage, const MustangJoints& p) {
  double margin = linkage.loop_margin(0, p);
  for (int k = 1; k < MustangClosure::loops; ++k) margin = std::min(margin, linkage.loop_margin(k, p));
  return margin;
}

// The sum of the link lengths and the shortest link: the scales of the closed-form bound.
double links_sum(const MustangLengths& L) {
  return L.l0_1 + L.l1_2 + L.l1_3 + L.l3_4 + L.l0_5 + L.l2_4 + L.l4_6 + L.l6_7 + L.l5_6 + L.l6_8 + L.l8_9 + L.l7_10 +
         L.l10_8 + L.l10_11 + L.l9_11 + L.l11_12;
}
constexpr double shortest_link = 1.0;  // l0_1, l1_2, l8_9, l9_11

// The pose at requested angle `requested`, solved and checked at `deg`, the same angle whole turns away.
MustangPose checked_pose(const MustangLinkage& linkage, double requested, double deg, const MustangAngles& x,
                         const PoseOutcome& outcome, bool checks) {
  MustangPose pose;
  pose.crank_deg = requested;
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
  pose.closed_form_bound = closed_form_bound(MustangClosure(deg * degrees), x, links_sum(MustangLengths{})).bound;
  return pose;
}

}  // namespace

void MustangSweepStepper::start(double start_deg, double stop_deg, double step_deg) {
  const int count = sweep_pose_count(start_deg, stop_deg, step_deg);
  sweep_ = MustangSweep{};
  poses_found_.clear();
  step_deg_ = step_deg;
  marching_ = options_;
  marching_.max_step_deg = std::min(options_.max_step_deg, std::abs(step_deg));
  // The requested angles, each marched to at the angle whole turns from it nearest the start (the
  // same pose; itself within half a turn), split there: those above it marched upwards, the rest
  // downwards.
  up_.clear();
  down_.clear();
  for (int i = 0; i < count; ++i) {
    const double angle = start_deg + i * step_deg;
    const Target target{angle, nearest_turn(angle, MustangClosure::seed_crank_deg)};
    (target.at >= MustangClosure::seed_crank_deg ? up_ : down_).push_back(target);
  }
  std::sort(up_.begin(), up_.end(), [](const Target& a, const Target& b) { return a.at < b.at; });
  std::sort(down_.begin(), down_.end(), [](const Target& a, const Target& b) { return a.at > b.at; });
  seeded_ = false;
  stop_requested_ = false;
  stopped_ = false;
  poses_ = 0;
  status_ = Status::running;
}

bool MustangSweepStepper::step() {
  if (!running()) return false;
  if (seeded_) {
    reach_next_target();
  } else {
    start_from_seed();
  }
  if (stop_requested_ && running()) stopped_ = true;  // the observer ended the run: no verdict
  return running();
}

MustangSweep MustangSweepStepper::solve(double start_deg, double stop_deg, double step_deg) {
  start(start_deg, stop_deg, step_deg);
  while (step()) {
  }
  return std::move(sweep_);
}

// 1. Seed 003's start at 45 deg.
bool MustangSweepStepper::start_from_seed() {
  const MustangStart start = mustang_seed_start();
  seeded_ = true;
  if (start.status != Status::converged) {
    sweep_.status = status_ = start.status;
    return false;
  }
  ++poses_;
  start_x_ = start.x;
  begin_direction(+1);
  if (up_.empty()) begin_direction(-1);
  return down_.empty() && up_.empty() ? finish() : true;
}

void MustangSweepStepper::begin_direction(int direction) {
  direction_ = direction;
  next_target_ = 0;
  x_ = start_x_;
  previous_ = MustangAngles::Zero();
  deg_ = MustangClosure::seed_crank_deg;
  previous_step_ = 0.0;
  has_previous_ = false;
}

// 2. The next requested angle in this direction; a limit ends the direction.
bool MustangSweepStepper::reach_next_target() {
  const std::vector<Target>& targets = direction_ > 0 ? up_ : down_;
  MustangLimit& limit = direction_ > 0 ? sweep_.upper : sweep_.lower;
  const Target target = targets[next_target_];
  PoseOutcome outcome;
  bool direction_done = true;
  if (advance_to(target.at, outcome, limit)) {
    poses_found_.push_back(checked_pose(linkage_, target.requested, target.at, x_, outcome, options_.checks));
    ++poses_;
    direction_done = ++next_target_ == targets.size();
  }
  if (!direction_done) return true;
  if (direction_ > 0 && !down_.empty()) {
    begin_direction(-1);
    return true;
  }
  return finish();
}

// Moves to target_deg; false (with the limit filled in) if the sweep had to stop before it.
bool MustangSweepStepper::advance_to(double target_deg, PoseOutcome& last, MustangLimit& limit) {
  // The walk from the start to the direction's first angle takes steps of its own (options'
  // max_step_deg), whatever the requested step; from one requested angle to the next, no step is
  // larger than the requested step.
  const double largest_step = next_target_ == 0 ? options_.max_step_deg : marching_.max_step_deg;
  double step = std::min(largest_step, std::abs(target_deg - deg_));
  if (step == 0.0) {  // already there: refine once, for the pose's own outcome
    last = solver_.solve(deg_ * degrees, x_);
    if (last.status == Status::converged) return true;
    limit = diagnose(deg_, last);
    return false;
  }
  while (deg_ != target_deg) {
    // 2. The next angle: one step on, or the target when it is that close.
    const bool last_step = std::abs(target_deg - deg_) <= step;
    const double next = last_step ? target_deg : deg_ + direction_ * step;
    // 3. Predict, correct, and check the branch; retry from the last pose if that fails.
    PoseOutcome outcome;
    MustangAngles trial;
    const bool ok = try_solve(next, true, trial, outcome) || (has_previous_ && try_solve(next, false, trial, outcome));
    if (ok) {
      previous_ = x_;
      previous_step_ = next - deg_;
      has_previous_ = true;
      x_ = trial;
      deg_ = next;
      last = outcome;
      continue;  // keep the step: after a halving this is the next bisection point
    }
    // 4. Failed: halve the step (a bisection between the last pose and the failed angle),
    //    until the bracket is below the resolution.
    if (step <= marching_.resolution_deg) {
      limit = diagnose(next, outcome);
      return false;
    }
    step *= 0.5;
    ++sweep_.step_halvings;
  }
  return true;
}

bool MustangSweepStepper::try_solve(double next, bool predict, MustangAngles& trial, PoseOutcome& outcome) {
  trial = x_;
  if (predict && has_previous_) trial += (x_ - previous_) * ((next - deg_) / previous_step_);
  outcome = solver_.solve(next * degrees, trial);
  const bool converged = outcome.status == Status::converged && trial.allFinite();
  const bool ok = converged && MustangLinkage::on_seed_branch(linkage_.joints(next * degrees, trial));
  // Once told to stop, the rest of this step goes unobserved; the run ends with it.
  if (observer_ != nullptr && !stop_requested_ &&
      observer_->on_step(*this, {next, next - deg_, outcome, ok, trial}) == StepControl::stop) {
    stop_requested_ = true;
  }
  return ok;
}

// Past the last pose: does the linkage close `resolution` further on? If not, that is the limit.
MustangLimit MustangSweepStepper::diagnose(double failed_deg, const PoseOutcome& outcome) const {
  MustangLimit limit;
  limit.reached = true;
  limit.last_assembled_deg = deg_;
  limit.failed_deg = failed_deg;
  limit.solver_loop = solver_.failed_loop();  // of the last solve, the one that failed
  const MustangClosedForm beyond = linkage_.closed_form((deg_ + direction_ * marching_.resolution_deg) * degrees);
  if (beyond.status == Status::cannot_assemble) {
    limit.status = Status::cannot_assemble;
    limit.loop = beyond.failed_loop;
  } else {
    limit.status = outcome.status == Status::converged ? Status::no_progress : outcome.status;  // left the branch
    limit.loop = solver_.failed_loop();
  }
  return limit;
}

// The poses in the requested order, with the checks summed up; the verdict.
bool MustangSweepStepper::finish() {
  std::vector<MustangPose>& poses = poses_found_;
  const double step_deg = step_deg_;
  std::sort(poses.begin(), poses.end(), [&](const MustangPose& a, const MustangPose& b) {
    return step_deg > 0 ? a.crank_deg < b.crank_deg : a.crank_deg > b.crank_deg;
  });
  MustangSweep& sweep = sweep_;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const MustangPose& pose = poses[i];
    sweep.worst_closed_form_distance = std::max(sweep.worst_closed_form_distance, pose.closed_form_distance);
    sweep.worst_closed_form_bound = std::max(sweep.worst_closed_form_bound, pose.closed_form_bound);
    if (!closed_form_verified(pose.closed_form_distance, pose.closed_form_bound, shortest_link)) {
      sweep.branch_kept = false;
    }
    sweep.worst_length_error = std::max(sweep.worst_length_error, pose.length_error);
    sweep.worst_rigid_error = std::max(sweep.worst_rigid_error, pose.rigid_error);
    sweep.worst_fixed_error = std::max(sweep.worst_fixed_error, pose.fixed_error);
    if (i > 0) {
      const double dtheta = std::abs(pose.crank_deg - poses[i - 1].crank_deg) * degrees;
      sweep.worst_angle_rate =
          std::max(sweep.worst_angle_rate, (pose.angles - poses[i - 1].angles).lpNorm<Eigen::Infinity>() / dtheta);
    }
  }
  sweep.poses = std::move(poses);
  poses.clear();
  sweep.status = Status::converged;  // unless a limit was reached or a pose is not verified
  for (const MustangLimit* limit : {&sweep.lower, &sweep.upper}) {
    if (limit->reached && sweep.status == Status::converged) sweep.status = limit->status;
  }
  // Poses the closed form does not confirm within their bound: not a converged sweep.
  if (!sweep.branch_kept && sweep.status == Status::converged) sweep.status = Status::no_progress;
  status_ = sweep.status;
  return false;
}

MustangSweep mustang_sweep(MustangPoseSolver& solver, double start_deg, double stop_deg, double step_deg,
                           const MustangSweepOptions& options, SweepObserver<MustangSweepStepper>* observer) {
  MustangSweepStepper stepper(solver, options);
  stepper.set_observer(observer);
  return stepper.solve(start_deg, stop_deg, step_deg);
}

double mustang_smallest_margin(double theta, const MustangAngles& x) {
  const MustangLinkage linkage;
  return smallest_margin(linkage, linkage.joints(theta, x));
}

}  // namespace numlab::mechanisms
