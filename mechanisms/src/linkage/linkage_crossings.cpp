#include "linkage_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "linkage_joints.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms::detail {

namespace {

// The size the rounding of a dyad's margin is measured against: its lengths and its centres' distance.
double dyad_size(const LinkageSolver& solver, const LinkageBlock& block, const Eigen::VectorXd& q) {
  const auto [first, second] = dyad_parts(solver.model(), block);
  const int joint = block.joints[0];
  double size = first->length + (joint_at(solver.model(), q, centre_of(*first, joint))).norm();
  if (block.kind == BlockKind::circle_circle) size += second->length;
  return size;
}

}  // namespace

namespace {

// The margin at t along the closed form from the tangent's prediction (q0 + velocity (t - t0)).
double margin_from(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0,
                   const Eigen::VectorXd& velocity, double t) {
  // The margin reads only the dyad's centres, which the blocks before it placed: it is defined even
  // where rounding makes this dyad itself fail at the meeting point.
  const Eigen::VectorXd start = velocity.allFinite() ? Eigen::VectorXd(q0 + velocity * (t - t0)) : q0;
  const LinkageSolution closed = solver.closed_form(t, start);
  const bool earlier_failed = closed.failed_block >= 0 && closed.failed_block < static_cast<int>(b);
  return earlier_failed ? -1.0 : solver.dyad_margins(closed.q)[b];
}

}  // namespace

double contact_order(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0, double meet, double d) {
  const Eigen::VectorXd velocity = linkage_velocity(solver.model(), t0, q0);
  const double far = margin_from(solver, b, t0, q0, velocity, meet + d), near = margin_from(solver, b, t0, q0, velocity, meet + 0.5 * d);
  return far > 0.0 && near > 0.0 ? std::log2(far / near) : std::numeric_limits<double>::quiet_NaN();
}

double change_point(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0, double t1,
                    bool at_start) {
  if (!solver.blocks()[b].dyad()) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXd velocity = linkage_velocity(solver.model(), t0, q0);
  const auto margin_at = [&](double t) { return margin_from(solver, b, t0, q0, velocity, t); };
  constexpr double golden = 0.6180339887498949;
  double a = t0, c = t1;
  for (int i = 0; i < 80 && std::abs(c - a) > 1e-12 * (1.0 + std::abs(t0)); ++i) {
    const double x1 = c - golden * (c - a), x2 = a + golden * (c - a);
    if (margin_at(x1) < margin_at(x2)) c = x2;
    else a = x1;
  }
  // The ends too: a sweep's pose may lie on the meeting point itself.
  double meet = 0.5 * (a + c), margin = margin_at(meet);
  for (const double end : {t0, t1}) {
    const double at_end = margin_at(end);
    if (at_end >= 0.0 && at_end < margin) {
      meet = end;
      margin = at_end;
    }
  }
  // A smallest margin at t0 itself belongs to the interval before, unless asked for. A margin that
  // grows like d^2 is at rounding level within about sqrt(eps) of its zero, so the search places it
  // only to about 1e-8: that close to t0 is t0.
  if (!at_start && std::abs(meet - t0) <= std::max(1e-9 * std::abs(t1 - t0), 1e-7 * (1.0 + std::abs(t0)))) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double scale = dyad_size(solver, solver.blocks()[b], q0);
  // Zero to rounding (a little below zero is rounding too), and no further below: below is a limit.
  // The search ends within 1e-12 of the meeting point, where a margin growing like d^2 is far below
  // 1e-13 of the size (the margin's own rounding is a few eps of it); a minimum that is not a
  // meeting point is above it unless the poses are within about 1e-7 of one, where the two
  // branches are one to that distance.
  return margin >= -1e-12 * scale && margin <= 1e-13 * scale ? meet : std::numeric_limits<double>::quiet_NaN();
}

bool side_defined_at(const LinkageSolver& solver, std::size_t b, const Eigen::VectorXd& q, double margin) {
  const LinkageBlock& block = solver.blocks()[b];
  if (!block.dyad()) return true;
  // The two solutions are 2 sqrt(2 r margin) apart near the meeting point. The pose's joints are
  // only as exact as the residual test makes them: a margin within ten residual tolerances of zero
  // (or at rounding level) could be the other side's, and the two solutions are within about
  // sqrt(tol) of the size of each other there.
  return margin > 1e-14 * dyad_size(solver, block, q) + 10.0 * solver.options().newton.residual_tolerance;
}

bool side_defined(const LinkageSolver& solver, std::size_t b, const Eigen::VectorXd& q) {
  return side_defined_at(solver, b, q, solver.blocks()[b].dyad() ? solver.dyad_margins(q)[b] : 0.0);
}

std::string side_word(const LinkageSolver& solver, std::size_t b, int side) {
  switch (solver.blocks()[b].kind) {
    case BlockKind::circle_circle: return side > 0 ? "left" : "right";
    case BlockKind::circle_line: return side > 0 ? "ahead" : "behind";
    case BlockKind::newton: return side > 0 ? "+" : "-";
    default: return "-";
  }
}

bool mirror_dyad(const LinkageSolver& solver, std::size_t b, Eigen::VectorXd& q) {
  const LinkageBlock& block = solver.blocks()[b];
  if (!block.dyad()) return false;
  const LinkageModel& model = solver.model();
  const int joint = block.joints[0];
  const Eigen::Vector2d p = joint_at(model, q, joint);
  const auto [first, second] = dyad_parts(model, block);
  const Eigen::Vector2d k1 = joint_at(model, q, centre_of(*first, joint));
  Eigen::Vector2d mirrored;
  if (block.kind == BlockKind::circle_circle) {
    const Eigen::Vector2d axis = joint_at(model, q, centre_of(*second, joint)) - k1;
    if (axis.squaredNorm() == 0.0) return false;
    const Eigen::Vector2d along = k1 + (p - k1).dot(axis) / axis.squaredNorm() * axis;  // the foot on the centres' line
    mirrored = 2.0 * along - p;
  } else {
    mirrored = 2.0 * foot_on_line(*second, k1) - p;  // across the foot of the centre on the line
  }
  set_joint(model, q, joint, mirrored);
  return true;
}

void keep_smooth_sides(const LinkageSolver& solver, double t0, const Eigen::VectorXd& q0, double t, Eigen::VectorXd& q) {
  const auto& blocks = solver.blocks();
  if (std::none_of(blocks.begin(), blocks.end(), [](const LinkageBlock& b) { return b.dyad(); })) return;
  const std::vector<double> m0 = solver.dyad_margins(q0), m1 = solver.dyad_margins(q);
  std::vector<int> s0, s1;  // the sides before and after, read once when a dyad is near meeting
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (!blocks[b].dyad() || !(std::min(m0[b], m1[b]) <= 1e-3 * solver.size())) continue;
    if (!side_defined_at(solver, b, q0, m0[b]) || !side_defined_at(solver, b, q, m1[b])) continue;
    if (s0.empty()) s0 = solver.signature(q0, t0), s1 = solver.signature(q, t);
    const int before = s0[b], after = s1[b];
    const double meet = change_point(solver, b, t0, q0, t, false);  // t0's side is defined: not on it
    bool crossed = false;
    if (std::isfinite(meet)) {
      const double d = std::abs(t - meet) >= std::abs(meet - t0) ? t - meet : t0 - meet;
      crossed = contact_order(solver, b, t0, q0, meet, d) < 3.0;
    }
    if ((crossed ? -before : before) == after) continue;
    Eigen::VectorXd other = q;
    if (!mirror_dyad(solver, b, other)) continue;
    const LinkageSolution closed = solver.closed_form(t, other);
    if (closed.failed_block < 0) other = closed.q;
    if (auto polished = solve_to_rounding(solver, t, other)) {
      if (solver.signature(*polished, t)[b] != after) {
        q = std::move(*polished);
        s1 = solver.signature(q, t);  // the later blocks read q's sides as it is now
      }
    }
  }
}

}  // namespace numlab::mechanisms::detail
