#include "linkage_fast_kernels.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "linkage_joints.hpp"
#include "linkage_rows.hpp"

namespace numlab::mechanisms::detail {

namespace {

Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

}  // namespace

Eigen::Vector2d rows_of(const LinkageModel& model, const Constraint& c, const Eigen::VectorXd& q, double t,
                        const Eigen::Vector2d& crank_direction) {
  const auto p = [&](int slot) { return joint_at(model, q, c.joints[static_cast<std::size_t>(slot)]); };
  switch (c.kind) {
    case ConstraintKind::distance: return {((p(0) - p(1)).squaredNorm() - c.length * c.length) / (2.0 * c.length), 0.0};
    case ConstraintKind::body_point: {
      const Eigen::Vector2d base = p(1) - p(0);
      return p(2) - p(0) - c.coefficients.x() * base - c.coefficients.y() * perp(base);
    }
    case ConstraintKind::slider_line: return {cross(c.direction, p(0) - c.point), 0.0};
    case ConstraintKind::crank: return p(1) - p(0) - c.length * (c.held ? c.direction : crank_direction);
    case ConstraintKind::slider_travel: return {c.direction.dot(p(0) - c.point) - (c.held ? c.held_value : t), 0.0};
    case ConstraintKind::slider_on_line: return {line_slot_row(p(0), p(1), p(2), c.offset).value, 0.0};
    case ConstraintKind::actuator: return {(p(0) - p(1)).norm() - (c.held ? c.held_value : t), 0.0};
    case ConstraintKind::motor: return {motor_row(p(0), p(1), p(2), t, c.length).value, 0.0};
  }
  return Eigen::Vector2d::Zero();
}

Eigen::Matrix2d partial_of(const LinkageModel& model, const Constraint& c, const Eigen::VectorXd& q, double t, int joint) {
  const auto p = [&](int slot) { return joint_at(model, q, c.joints[static_cast<std::size_t>(slot)]); };
  const auto pick = [&](const Eigen::Vector2d& d0, const Eigen::Vector2d& d1, const Eigen::Vector2d& d2) {
    return joint == c.joints[0] ? d0 : joint == c.joints[1] ? d1 : d2;
  };
  Eigen::Matrix2d d = Eigen::Matrix2d::Zero();
  if (joint != c.joints[0] && joint != c.joints[1] && joint != c.joints[2]) return d;  // c does not read it
  switch (c.kind) {
    case ConstraintKind::distance: {
      const Eigen::Vector2d g = (joint_at(model, q, c.joints[0]) - joint_at(model, q, c.joints[1])) / c.length;
      d.row(0) = joint == c.joints[0] ? g.transpose() : Eigen::RowVector2d(-g.transpose());
      break;
    }
    case ConstraintKind::body_point: {
      Eigen::Matrix2d along;  // a I + b R, R the quarter turn
      along << c.coefficients.x(), -c.coefficients.y(), c.coefficients.y(), c.coefficients.x();
      if (joint == c.joints[0]) d = along - Eigen::Matrix2d::Identity();
      else if (joint == c.joints[1]) d = -along;
      else d.setIdentity();
      break;
    }
    case ConstraintKind::slider_line: d.row(0) << -c.direction.y(), c.direction.x(); break;
    case ConstraintKind::crank: d = joint == c.joints[0] ? Eigen::Matrix2d(-Eigen::Matrix2d::Identity()) : Eigen::Matrix2d::Identity(); break;
    case ConstraintKind::slider_travel: d.row(0) = c.direction.transpose(); break;
    case ConstraintKind::slider_on_line: {
      const LineSlotRow slot = line_slot_row(p(0), p(1), p(2), c.offset);
      d.row(0) = pick(slot.dA, slot.dB, slot.dC).transpose();
      break;
    }
    case ConstraintKind::actuator: {
      const Eigen::Vector2d g = actuator_gradient(p(0), p(1), c.length);
      d.row(0) = pick(g, -g, Eigen::Vector2d::Zero()).transpose();
      break;
    }
    case ConstraintKind::motor: {
      const MotorRow motor = motor_row(p(0), p(1), p(2), t, c.length);
      d.row(0) = pick(motor.dA, motor.dB, motor.dC).transpose();
      break;
    }
  }
  return d;
}

Status sparse_gepp(RowMajorMatrix& work, const Eigen::VectorXd& f, Eigen::VectorXd& rhs, Eigen::VectorXd& inverse_pivots,
                   Eigen::VectorXd& dx) {
  const Eigen::Index n = work.rows();
  const double negligible = static_cast<double>(n) * std::numeric_limits<double>::epsilon() * work.cwiseAbs().maxCoeff();
  rhs = -f;
  for (Eigen::Index k = 0; k < n; ++k) {
    // 1. The pivot: the first row p >= k with the largest |u_pk|.
    Eigen::Index p = k;
    for (Eigen::Index i = k + 1; i < n; ++i) {
      if (std::abs(work(i, k)) > std::abs(work(p, k))) p = i;
    }
    // 2. Rows k and p swapped.
    if (p != k) {
      work.row(k).swap(work.row(p));
      std::swap(rhs(k), rhs(p));
    }
    const double pivot = work(k, k);
    if (!std::isfinite(pivot)) return Status::non_finite;
    if (std::abs(pivot) <= negligible) return Status::singular;
    // 3. Each row below with a nonzero multiplier l_ik = u_ik / u_kk: row_i -= l_ik row_k.
    inverse_pivots(k) = 1.0 / pivot;
    for (Eigen::Index i = k + 1; i < n; ++i) {
      const double multiplier = work(i, k) * inverse_pivots(k);
      if (multiplier == 0.0) continue;
      work(i, k) = 0.0;
      work.row(i).tail(n - k - 1) -= multiplier * work.row(k).tail(n - k - 1);
      rhs(i) -= multiplier * rhs(k);
    }
  }
  // 4. Back substitution, column by column from the last unknown.
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    dx(i) = rhs(i) * inverse_pivots(i);
    if (!std::isfinite(dx(i))) return Status::non_finite;
    rhs.head(i) -= work.col(i).head(i) * dx(i);
  }
  return Status::converged;
}

void whole_residual(const LinkageModel& model, const Eigen::VectorXd& q, double t, const Eigen::Vector2d& crank_direction,
                    Eigen::VectorXd& f) {
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const Constraint& c = model.constraints()[k];
    const Eigen::Vector2d rows = rows_of(model, c, q, t, crank_direction);
    const int row = model.first_row(static_cast<int>(k));
    f(row) = rows(0);
    if (c.rows() == 2) f(row + 1) = rows(1);
  }
}

}  // namespace numlab::mechanisms::detail
