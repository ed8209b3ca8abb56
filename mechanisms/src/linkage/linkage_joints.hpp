#pragma once
// Internal to the linkage solvers (linkage_solver.cpp, linkage_fast_solver.cpp): reading and placing
// joints in the unknowns, the parts of a dyad, and the closed form of the blocks, which both the
// generic solver and its fast path run.

#include <Eigen/Core>
#include <cmath>
#include <utility>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

namespace numlab::mechanisms::detail {

inline Eigen::Vector2d joint_at(const LinkageModel& model, const Eigen::VectorXd& q, int joint) {
  const int column = model.column_of(joint);
  return column < 0 ? model.description().joints[static_cast<std::size_t>(joint)].position
                    : Eigen::Vector2d(q(column), q(column + 1));
}

inline void set_joint(const LinkageModel& model, Eigen::VectorXd& q, int joint, const Eigen::Vector2d& p) {
  q.segment<2>(model.column_of(joint)) = p;
}

inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The other joint of a distance constraint (its circle's centre) for the block's joint.
inline int centre_of(const Constraint& c, int joint) { return c.joints[0] == joint ? c.joints[1] : c.joints[0]; }

// A dyad's two constraints: for circle-line, the distance first.
struct DyadParts {
  const Constraint* first;
  const Constraint* second;
};

inline DyadParts dyad_parts(const LinkageModel& model, const LinkageBlock& block) {
  const Constraint* a = &model.constraints()[static_cast<std::size_t>(block.constraints[0])];
  const Constraint* b = &model.constraints()[static_cast<std::size_t>(block.constraints[1])];
  if (a->kind != ConstraintKind::distance) std::swap(a, b);
  return {a, b};
}

// The foot of the perpendicular from `point` onto a slider's line.
inline Eigen::Vector2d foot_on_line(const Constraint& line, const Eigen::Vector2d& point) {
  return line.point + (point - line.point).dot(line.direction) * line.direction;
}

// (cos, sin)(t + offset) of the model's driving crank; zero when no crank drives.
inline Eigen::Vector2d crank_direction(const LinkageModel& model, double t) {
  for (const Constraint& c : model.constraints()) {
    if (c.kind == ConstraintKind::crank && !c.held) return {std::cos(t + c.offset), std::sin(t + c.offset)};
  }
  return Eigen::Vector2d::Zero();
}

// The closed form of one block, in place (a dyad takes, of its two solutions, the one nearer its
// joint's place in q). False when the block has no closed form or cannot close. Allocates nothing.
bool place_block(const LinkageModel& model, const LinkageBlock& block, double t, const Eigen::Vector2d& crank_direction,
                 Eigen::VectorXd& q);

// The verdict on an explicit block (placed_directly) from its rows evaluated at the placed joint:
// no Newton iteration, one evaluation of its rows, converged only when they pass the residual test
// (they are at rounding level unless the input is impossible: non-finite, or too large for the
// tolerance).
inline nonlinear::NewtonCounts placed_block_counts(const Eigen::Vector2d& rows, double residual_tolerance) {
  nonlinear::NewtonCounts counts;
  counts.function_evaluations = 1;
  counts.residual_norm = rows.lpNorm<Eigen::Infinity>();
  if (!rows.allFinite()) {
    counts.status = Status::non_finite;
    counts.reason = nonlinear::StopReason::non_finite;
  } else if (nonlinear::residual_small(counts.residual_norm, residual_tolerance)) {
    counts.status = Status::converged;
    counts.reason = nonlinear::StopReason::residual_small;
  } else {
    counts.status = Status::no_progress;
    counts.reason = nonlinear::StopReason::no_progress;
  }
  return counts;
}

// The closed form of every block in order, in place: q holds the start (a dyad takes, of its two
// solutions, the one nearer its joint's place in q) and then the result. Returns the first block
// that has no closed form or cannot close, or -1. Allocates nothing.
int closed_form_in_place(const LinkageModel& model, const std::vector<LinkageBlock>& blocks, double t, Eigen::VectorXd& q);
// The same with the crank's direction at t already at hand (crank_direction above).
int closed_form_in_place(const LinkageModel& model, const std::vector<LinkageBlock>& blocks, double t,
                         const Eigen::Vector2d& crank_direction, Eigen::VectorXd& q);

}  // namespace numlab::mechanisms::detail
