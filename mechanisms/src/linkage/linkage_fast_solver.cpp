#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "linkage_fast_kernels.hpp"
#include "linkage_fast_sparse.hpp"
#include "linkage_joints.hpp"
#include "numlab/linalg/input_checks.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"

namespace numlab::mechanisms {

namespace {

using detail::newton_in_place;
using detail::partial_of;
using detail::rows_of;
using detail::RowMajorMatrix;
using detail::sparse_gepp;
using detail::whole_residual;
using nonlinear::NewtonCounts;
using nonlinear::StopReason;

// The whole system, for full Newton. J is put straight into the work matrix GEPP overwrites, with
// row k at row_at[k] and column k at column_at[k]; f goes in, and dx comes out, through the same
// layout.
struct WholeProblem {
  const LinkageModel& model;
  double t;
  Eigen::Vector2d crank_direction;
  const std::vector<int>& row_at;
  const std::vector<int>& column_at;
  RowMajorMatrix& work;
  Eigen::VectorXd& laid_out_f;
  Eigen::VectorXd& laid_out_dx;
  Eigen::VectorXd& rhs;
  Eigen::VectorXd& inverse_pivots;
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const { whole_residual(model, x, t, crank_direction, f); }
  bool jacobian(const Eigen::VectorXd& x) const {
    work.setZero();
    for (std::size_t k = 0; k < model.constraints().size(); ++k) {
      const Constraint& c = model.constraints()[k];
      const int first_row = model.first_row(static_cast<int>(k));
      for (const int joint : c.joints) {
        if (joint < 0 || model.column_of(joint) < 0) continue;  // unused slot, or a ground joint
        const Eigen::Matrix2d d = partial_of(model, c, x, t, joint);
        for (int r = 0; r < c.rows(); ++r) {
          for (int xy = 0; xy < 2; ++xy) work(at(row_at, first_row + r), at(column_at, model.column_of(joint) + xy)) = d(r, xy);
        }
      }
    }
    return linalg::all_finite(work);
  }
  Status solve(const Eigen::VectorXd& f, Eigen::VectorXd& dx) const {
    for (Eigen::Index k = 0; k < f.size(); ++k) laid_out_f(at(row_at, k)) = f(k);
    const Status status = sparse_gepp(work, laid_out_f, rhs, inverse_pivots, laid_out_dx);
    for (Eigen::Index k = 0; k < dx.size(); ++k) dx(k) = laid_out_dx(at(column_at, k));
    return status;
  }
  static Eigen::Index at(const std::vector<int>& layout, Eigen::Index k) { return layout[static_cast<std::size_t>(k)]; }
};

// J dx = -f for a one-joint block's fixed 2x2 J, by the closed-form inverse.
Status closed_form_step(const Eigen::Matrix2d& J, const Eigen::Vector2d& f, Eigen::Vector2d& dx) {
  const linalg::LinearResult<2> step = linalg::ClosedForm2x2().solve_prechecked(J, -f);
  dx = step.x;
  return step.status;
}

// A one-joint block: two rows, the joint's x and y, a fixed 2x2 system.
struct JointProblem {
  const LinkageModel& model;
  const LinkageFastSolver::Block& block;
  double t;
  Eigen::Vector2d crank_direction;
  Eigen::VectorXd& q;
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  void place(const Eigen::Vector2d& x) const { q.segment<2>(block.columns[0]) = x; }
  void residual(const Eigen::Vector2d& x, Eigen::Vector2d& f) const {
    place(x);
    for (const LinkageFastSolver::Part& part : block.parts) {
      const Eigen::Vector2d rows = rows_of(model, *part.constraint, q, t, crank_direction);
      for (int r = 0; r < 2; ++r) {
        if (part.row[r] >= 0) f(part.row[r]) = rows(r);
      }
    }
  }
  bool jacobian(const Eigen::Vector2d& x) {
    place(x);
    for (const LinkageFastSolver::Part& part : block.parts) {
      const Eigen::Matrix2d d = partial_of(model, *part.constraint, q, t, block.joints[0]);
      for (int r = 0; r < 2; ++r) {
        if (part.row[r] >= 0) J.row(part.row[r]) = d.row(r);
      }
    }
    return J.allFinite();
  }
  Status solve(const Eigen::Vector2d& f, Eigen::Vector2d& dx) const { return closed_form_step(J, f, dx); }
};

// A circle-circle dyad: the joint x on two circles whose centres a_r (joints of earlier blocks, or
// ground) stay put while the block is solved. Rows and derivatives are those rows_of and partial_of
// give for the two distance constraints, computed alike, from the centres read once.
struct TwoCirclesProblem {
  std::array<Eigen::Vector2d, 2> centre;
  std::array<double, 2> radius;
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  void residual(const Eigen::Vector2d& x, Eigen::Vector2d& f) const {
    for (int r = 0; r < 2; ++r) f(r) = ((x - centre[r]).squaredNorm() - radius[r] * radius[r]) / (2.0 * radius[r]);
  }
  bool jacobian(const Eigen::Vector2d& x) {
    for (int r = 0; r < 2; ++r) J.row(r) = ((x - centre[r]) / radius[r]).transpose();
    return J.allFinite();
  }
  Status solve(const Eigen::Vector2d& f, Eigen::Vector2d& dx) const { return closed_form_step(J, f, dx); }
};

// A block of several joints: its rows and columns only, GEPP on its preallocated work matrix.
struct BlockProblem {
  const LinkageModel& model;
  LinkageFastSolver::Block& block;
  double t;
  Eigen::Vector2d crank_direction;
  Eigen::VectorXd& q;
  void place(const Eigen::VectorXd& x) const {
    for (int j = 0; j < block.size; ++j) q(block.columns[static_cast<std::size_t>(j)]) = x(j);
  }
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    place(x);
    for (const LinkageFastSolver::Part& part : block.parts) {
      const Eigen::Vector2d rows = rows_of(model, *part.constraint, q, t, crank_direction);
      for (int r = 0; r < 2; ++r) {
        if (part.row[r] >= 0) f(part.row[r]) = rows(r);
      }
    }
  }
  bool jacobian(const Eigen::VectorXd& x) const {
    place(x);
    for (const LinkageFastSolver::Part& part : block.parts) {
      for (std::size_t k = 0; k < block.joints.size(); ++k) {
        const Eigen::Matrix2d d = partial_of(model, *part.constraint, q, t, block.joints[k]);
        for (int r = 0; r < 2; ++r) {
          if (part.row[r] >= 0) block.work.block<1, 2>(part.row[r], 2 * static_cast<Eigen::Index>(k)) = d.row(r);
        }
      }
    }
    return linalg::all_finite(block.work);
  }
  Status solve(const Eigen::VectorXd& f, Eigen::VectorXd& dx) const {
    return sparse_gepp(block.work, f, block.rhs, block.inverse_pivots, dx);
  }
};

// The counts of a block's Newton added to the solve's, as solve_sequential adds them.
void add_block(NewtonCounts& total, const NewtonCounts& block) {
  total.iterations += block.iterations;
  total.jacobian_evaluations += block.jacobian_evaluations;
  total.function_evaluations += block.function_evaluations;
  total.step_norm = block.step_norm;
}

}  // namespace

bool LinkageFastSolver::applies(const LinkageSolverOptions& options) {
  if (options.newton.damped) return false;
  return (options.solver == "full" && options.linear == "gepp") || options.solver == "sequential" || options.solver == "analytic";
}

LinkageFastSolver::LinkageFastSolver(const LinkageSolver& solver) : solver_(solver) {
  if (!applies(solver.options())) {
    throw std::invalid_argument("the fast linkage path does not cover --solver " + solver.options().solver + " --linear " +
                                solver.options().linear + (solver.options().newton.damped ? " (damped)" : ""));
  }
  const LinkageModel& model = solver.model();
  const int n = model.unknown_count();
  f_.setZero(n), dx_.setZero(n), rhs_.setZero(n), inverse_pivots_.setZero(n), phi_t_.setZero(n), qdot_.setZero(n);
  if (n > linkage_exact_conditioning_limit) {
    sparse_ = std::make_unique<Sparse>();  // J sparse: no n x n matrix at all
  } else {
    J_.setZero(n, n);
    work_.setZero(n, n);
  }
  for (const Constraint& c : model.constraints()) {
    if (c.kind == ConstraintKind::crank && !c.held) crank_ = &c;
  }
  for (const LinkageBlock& source : solver.blocks()) {
    Block block;
    block.size = static_cast<int>(source.rows_and_columns.unknowns.size());
    block.rows = source.rows_and_columns.equations;
    block.columns = source.rows_and_columns.unknowns;
    block.joints = source.joints;
    // Each constraint with a row in the block, and where its rows go in the block's f.
    for (std::size_t k = 0; k < model.constraints().size(); ++k) {
      Part part{&model.constraints()[k], {-1, -1}};
      for (int r = 0; r < part.constraint->rows(); ++r) {
        const auto at = std::find(block.rows.begin(), block.rows.end(), model.first_row(static_cast<int>(k)) + r);
        if (at != block.rows.end()) part.row[r] = static_cast<int>(at - block.rows.begin());
      }
      if (part.row[0] >= 0 || part.row[1] >= 0) block.parts.push_back(part);
    }
    if (source.kind == BlockKind::circle_circle && block.parts.size() == 2) {
      block.two_circles = true;
      for (const Part& part : block.parts) {
        const std::size_t r = static_cast<std::size_t>(part.row[0]);
        block.centres[r] = detail::centre_of(*part.constraint, block.joints[0]);
        block.radii[r] = part.constraint->length;
      }
    }
    block.work.setZero(block.size, block.size);
    block.x.setZero(block.size), block.f.setZero(block.size), block.dx.setZero(block.size);
    block.rhs.setZero(block.size), block.inverse_pivots.setZero(block.size);
    blocks_.push_back(std::move(block));
  }
  lay_out_full_system(n);
}

// Full Newton's layout: the blocks from last to first, each block's rows and columns in its own
// order. J is block lower triangular in block order (a block's rows read its own joints and those of
// earlier blocks), so in reverse order it is block upper triangular: the entries below a pivot are
// in the pivot's own block, and GEPP's row updates stay inside it. Rows or columns in no block
// (none, for a model the blocks cover) keep their order after them.
void LinkageFastSolver::lay_out_full_system(int n) {
  full_row_at_.assign(static_cast<std::size_t>(n), -1);
  full_column_at_.assign(static_cast<std::size_t>(n), -1);
  int next_row = 0, next_column = 0;
  for (auto block = blocks_.rbegin(); block != blocks_.rend(); ++block) {
    for (const int row : block->rows) full_row_at_[static_cast<std::size_t>(row)] = next_row++;
    for (const int column : block->columns) full_column_at_[static_cast<std::size_t>(column)] = next_column++;
  }
  for (int& at : full_row_at_) {
    if (at < 0) at = next_row++;
  }
  for (int& at : full_column_at_) {
    if (at < 0) at = next_column++;
  }
  full_f_.setZero(n), full_dx_.setZero(n);
}

LinkageFastSolver::~LinkageFastSolver() = default;
LinkageFastSolver::LinkageFastSolver(LinkageFastSolver&&) noexcept = default;

LinkageFastOutcome LinkageFastSolver::solve(double t, Eigen::VectorXd& q) {
  if (q.size() != solver_.model().unknown_count()) {
    throw std::invalid_argument("starting point has " + std::to_string(q.size()) + " entries but the system has " +
                                std::to_string(solver_.model().unknown_count()) + " unknowns");
  }
  const std::string& kind = solver_.options().solver;
  if (kind == "full") return solve_full(t, q);
  if (kind == "sequential") return solve_sequential(t, q);
  return solve_analytic(t, q);
}

LinkageFastOutcome LinkageFastSolver::solve_full(double t, Eigen::VectorXd& q) {
  linalg::require_finite(q, "starting point");
  if (sparse_) {
    const detail::SparseWholeProblem whole{solver_.model(), t, crank_direction(t), *sparse_};
    return {newton_in_place(whole, q, f_, dx_, solver_.options().newton), -1};
  }
  WholeProblem whole{solver_.model(), t, crank_direction(t), full_row_at_, full_column_at_, work_, full_f_, full_dx_,
                     rhs_, inverse_pivots_};
  return {newton_in_place(whole, q, f_, dx_, solver_.options().newton), -1};
}

// The blocks in order, as LinkageSolver::solve_sequential, each on its own rows and columns.
LinkageFastOutcome LinkageFastSolver::solve_sequential(double t, Eigen::VectorXd& q) {
  LinkageFastOutcome solution;
  solution.outcome.status = Status::converged;
  solution.outcome.reason = StopReason::residual_small;
  const nonlinear::NewtonOptions& options = solver_.options().newton;
  const Eigen::Vector2d direction = crank_direction(t);
  double worst_row = 0.0;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    Block& block = blocks_[b];
    NewtonCounts counts;
    if (solver_.blocks()[b].placed_directly()) {  // placed by its formula, its rows then checked
      detail::place_block(solver_.model(), solver_.blocks()[b], t, direction, q);
      Eigen::Vector2d f;
      JointProblem problem{solver_.model(), block, t, direction, q, Eigen::Matrix2d::Zero()};
      problem.residual(q.segment<2>(block.columns[0]), f);
      counts = detail::placed_block_counts(f, options.residual_tolerance);
    } else if (block.two_circles) {
      Eigen::Vector2d x = q.segment<2>(block.columns[0]), f, dx;
      linalg::require_finite(x, "starting point");
      const auto centre = [&](int r) { return detail::joint_at(solver_.model(), q, block.centres[static_cast<std::size_t>(r)]); };
      TwoCirclesProblem problem{{centre(0), centre(1)}, block.radii};
      counts = newton_in_place(problem, x, f, dx, options);
      q.segment<2>(block.columns[0]) = x;
    } else if (block.size == 2) {
      Eigen::Vector2d x = q.segment<2>(block.columns[0]), f, dx;
      linalg::require_finite(x, "starting point");
      JointProblem problem{solver_.model(), block, t, direction, q, Eigen::Matrix2d::Zero()};
      counts = newton_in_place(problem, x, f, dx, options);
      problem.place(x);
    } else {
      for (int j = 0; j < block.size; ++j) block.x(j) = q(block.columns[static_cast<std::size_t>(j)]);
      linalg::require_finite(block.x, "starting point");
      BlockProblem problem{solver_.model(), block, t, direction, q};
      counts = newton_in_place(problem, block.x, block.f, block.dx, options);
      problem.place(block.x);
    }
    add_block(solution.outcome, counts);
    worst_row = std::max(worst_row, counts.residual_norm);
    if (counts.status != Status::converged) {
      solution.outcome.status = counts.status;
      solution.outcome.reason = counts.reason;
      solution.failed_block = static_cast<int>(b);
      break;
    }
  }
  // ||Phi||_inf at the result. When every block converged it is the largest of the blocks' own
  // final ||f||_inf: a block's rows read only its joints and those of the blocks before it, none of
  // which moved after it ended, so those rows are Phi's rows at the result, computed alike.
  solution.outcome.residual_norm = solution.failed_block < 0 ? worst_row : whole_residual_norm(q, t);
  if (solution.outcome.status == Status::converged && !(solution.outcome.residual_norm <= options.residual_tolerance)) {
    solution.outcome.status = Status::no_progress;
    solution.outcome.reason = StopReason::no_progress;
  }
  return solution;
}

// As LinkageSolver::closed_form, in place.
LinkageFastOutcome LinkageFastSolver::solve_analytic(double t, Eigen::VectorXd& q) {
  LinkageFastOutcome solution;
  const Eigen::Vector2d direction = crank_direction(t);  // once, for the blocks and the residual test
  solution.failed_block = detail::closed_form_in_place(solver_.model(), solver_.blocks(), t, direction, q);
  solution.outcome.status = solution.failed_block < 0 ? Status::converged : Status::cannot_assemble;
  solution.outcome.reason = solution.failed_block < 0 ? StopReason::residual_small : StopReason::running;
  whole_residual(solver_.model(), q, t, direction, f_);
  solution.outcome.residual_norm = f_.size() == 0 ? 0.0 : f_.lpNorm<Eigen::Infinity>();
  if (solution.failed_block < 0 && !(solution.outcome.residual_norm <= solver_.options().newton.residual_tolerance)) {
    solution.outcome.status = Status::no_progress;
    solution.outcome.reason = StopReason::no_progress;
  }
  return solution;
}

double LinkageFastSolver::whole_residual_norm(const Eigen::VectorXd& q, double t) {
  whole_residual(solver_.model(), q, t, crank_direction(t), f_);
  return f_.size() == 0 ? 0.0 : f_.lpNorm<Eigen::Infinity>();
}

Eigen::Vector2d LinkageFastSolver::crank_direction(double t) const {
  return crank_ == nullptr ? Eigen::Vector2d::Zero() : Eigen::Vector2d(std::cos(t + crank_->offset), std::sin(t + crank_->offset));
}

// Block forward substitution: block by block in solving order, A_bb qdot_b = -Phi_t,b - sum of the
// earlier blocks' A_bc qdot_c (the later blocks' entries are zero, and so are qdot's unsolved ones).
bool LinkageFastSolver::velocity(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
  const LinkageModel& model = solver_.model();
  if (sparse_) sparse_->read_rows(model, t, q);
  else model.jacobian(q, t, J_);
  model.driver_derivative(q, t, phi_t_);
  qdot.setZero(model.unknown_count());
  for (Block& block : blocks_) {
    for (int i = 0; i < block.size; ++i) {
      const int row = block.rows[static_cast<std::size_t>(i)];
      block.f(i) = phi_t_(row) + (sparse_ ? sparse_->row_dot(row, qdot) : J_.row(row).dot(qdot));  // the right-hand side is -f
      for (int j = 0; j < block.size; ++j) {
        const int column = block.columns[static_cast<std::size_t>(j)];
        block.work(i, j) = sparse_ ? sparse_->rows.coeff(row, column) : J_(row, column);
      }
    }
    Status status = Status::converged;
    if (block.size == 2) {
      const auto step = linalg::ClosedForm2x2().solve_prechecked(block.work, Eigen::Vector2d(-block.f));
      block.dx = step.x;
      status = step.status;
    } else {
      status = sparse_gepp(block.work, block.f, block.rhs, block.inverse_pivots, block.dx);
    }
    if (status != Status::converged) {
      qdot.setConstant(std::numeric_limits<double>::quiet_NaN());
      return false;
    }
    for (int j = 0; j < block.size; ++j) qdot(block.columns[static_cast<std::size_t>(j)]) = block.dx(j);
  }
  return true;
}

void LinkageFastSolver::predict(double at, Eigen::VectorXd& q, double next) {
  if (velocity(at, q, qdot_) && qdot_.allFinite()) q += qdot_ * (next - at);
}

}  // namespace numlab::mechanisms
