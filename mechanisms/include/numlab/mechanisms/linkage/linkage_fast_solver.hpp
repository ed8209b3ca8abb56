#pragma once
// The fast path beside LinkageSolver (linkage_solver.hpp), for sweeps and `numlab bench`: the same
// full, sequential and analytic solves, with the same stop tests, statuses, iterations and residual
// evaluations, on a workspace sized once when it is made. (Its jacobian_evaluations are one per
// iteration: the generic Newton on a DynamicSystem evaluates J with every residual, the last
// unused.) A solve, and each Newton iteration in it, allocates nothing on the heap.
//
// Where the time goes instead:
//   full        f and J into preallocated storage, J's nonzeros only, and GEPP in place that skips
//               the row updates whose multiplier is zero (J is sparse); J's rows and columns laid
//               out in reverse block order, so that J is block upper triangular and elimination
//               stays inside each diagonal block (no fill-in outside it)
//   sequential  per block only that block's own rows and columns: an explicit block (crank, body
//               point, driven slider) placed by its formula as the generic solver does, a one-joint
//               block by Newton on a fixed 2x2 system with the closed-form inverse (a circle-circle
//               dyad's from its two centres, read once per solve), a bigger block by that GEPP
//   analytic    the generic closed form itself, in place
// and the crank's cos and sin once per solve, not at every residual.
// and velocity() solves J qdot = -Phi_t block by block (J is block lower triangular in block order).
//
// tests/mechanisms/linkage/fast/ checks that both paths agree on every shipped model and that nothing is
// allocated. The teaching path, and --trace and --step, stay with LinkageSolver.

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::mechanisms {

struct LinkageFastOutcome {
  nonlinear::NewtonCounts outcome;
  int failed_block = -1;  // as LinkageSolution::failed_block
};

class LinkageFastSolver {
 public:
  // Whether the fast path covers these options: full with GEPP, sequential or analytic, undamped.
  static bool applies(const LinkageSolverOptions& options);

  // Sizes the workspace for the solver's model and blocks (the solver must outlive it). Throws
  // std::invalid_argument when applies(solver.options()) is false.
  explicit LinkageFastSolver(const LinkageSolver& solver);
  ~LinkageFastSolver();
  LinkageFastSolver(LinkageFastSolver&&) noexcept;
  LinkageFastSolver(const LinkageFastSolver&) = delete;
  LinkageFastSolver& operator=(const LinkageFastSolver&) = delete;
  LinkageFastSolver& operator=(LinkageFastSolver&&) = delete;

  const LinkageSolver& solver() const { return solver_; }

  // Solves at driver value t (model units), in place: q is the start, then the result, as
  // LinkageSolver::solve(t, q).q. Throws std::invalid_argument for a q of the wrong size or not
  // finite, as Newton does.
  LinkageFastOutcome solve(double t, Eigen::VectorXd& q);

  // dq/dt at a pose (J qdot = -Phi_t), into qdot (sized to the unknowns). False, and qdot not
  // finite, when a block of J is singular.
  bool velocity(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot);

  // The first-order predictor of continuation, in place: q + qdot (next - at); q unchanged when the
  // velocity is not finite (as the generic sweep's predictor).
  void predict(double at, Eigen::VectorXd& q, double next);

  // A constraint with rows in a block, and where they go in the block's f (-1: not in the block).
  // Public for the .cpp's helpers; not an interface.
  struct Part {
    const Constraint* constraint;
    std::array<int, 2> row;
  };
  // One block's precomputed rows and columns.
  struct Block {
    int size = 0;                       // unknowns (and rows)
    std::vector<int> rows, columns;     // of the whole system
    std::vector<Part> parts;
    std::vector<int> joints;            // the block's joints, in column order (x, y each)
    bool two_circles = false;           // a circle-circle dyad: its rows are two distance constraints
    std::array<int, 2> centres{-1, -1}; //   to these joints (solved earlier, or ground), in row order,
    std::array<double, 2> radii{};      //   with these lengths
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> work;  // bigger blocks: J, then U
    Eigen::VectorXd x, f, dx, rhs, inverse_pivots;
  };
  // J kept sparse, beyond linkage_exact_conditioning_limit unknowns (src/linkage/linkage_fast_sparse.hpp).
  struct Sparse;

 private:
  LinkageFastOutcome solve_full(double t, Eigen::VectorXd& q);
  LinkageFastOutcome solve_sequential(double t, Eigen::VectorXd& q);
  LinkageFastOutcome solve_analytic(double t, Eigen::VectorXd& q);
  void lay_out_full_system(int n);
  double whole_residual_norm(const Eigen::VectorXd& q, double t);
  Eigen::Vector2d crank_direction(double t) const;  // (cos, sin)(t + offset), once per solve

  const LinkageSolver& solver_;
  const Constraint* crank_ = nullptr;  // the driving crank's constraint, if a crank drives
  std::vector<Block> blocks_;
  // Full Newton's layout: where the model's row (column) k sits in the work matrix.
  std::vector<int> full_row_at_, full_column_at_;
  Eigen::VectorXd full_f_, full_dx_;  // f and dx in that layout
  Eigen::VectorXd f_, dx_, rhs_, inverse_pivots_, phi_t_, qdot_;
  Eigen::MatrixXd J_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> work_;
  std::unique_ptr<Sparse> sparse_;  // beyond linkage_exact_conditioning_limit unknowns
};

}  // namespace numlab::mechanisms
