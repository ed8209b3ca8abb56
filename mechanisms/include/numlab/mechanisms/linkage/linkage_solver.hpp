#pragma once
// Solving a derived linkage model at one driver value, with every solver numlab has:
//
//   full        Newton on the whole system, any inner linear solver (--linear)
//   sequential  the blocks in order (linkage_blocks.hpp): an explicit block (crank, body point,
//               driven slider) placed by its formula, no Newton iteration, its rows then checked;
//               Newton on every other block, the 2x2 closed-form inverse for two-unknown blocks,
//               GEPP for bigger ones
//   analytic    the closed form of every block (circle-circle, circle-line, explicit); refused when
//               a block needs Newton
//   gsl-<type>  GSL's multiroot solver of that type on the whole system
//
// The branch is the reference pose's: the constructor runs damped Newton from the file's rough
// positions at the reference driver value, and each dyad's side (and each Newton block's sign of
// det J) is read from that pose: its signature. Sweeps continue from it (linkage_sweep.hpp).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::mechanisms {

// Phi(q; t) = 0 at a fixed driver value t, as a nonlinear system for Newton and GSL.
class LinkageSystem final : public nonlinear::DynamicSystem {
 public:
  explicit LinkageSystem(const LinkageModel& model, double t = 0.0) : model_(model), t_(t) {}
  explicit LinkageSystem(const LinkageModel&&, double = 0.0) = delete;  // it keeps a reference to the model
  void set_driver(double t) { t_ = t; }
  double driver() const { return t_; }
  int dimension() const override { return model_.unknown_count(); }
  void residual(const Eigen::VectorXd& q, Eigen::VectorXd& f) const override { model_.residual(q, t_, f); }
  void jacobian(const Eigen::VectorXd& q, Eigen::MatrixXd& J) const override { model_.jacobian(q, t_, J); }

 private:
  const LinkageModel& model_;
  double t_;
};

// The names --solver takes: full, sequential, analytic, gsl-<type> for each GSL multiroot type.
const std::vector<std::string>& linkage_solver_names();

struct LinkageSolverOptions {
  std::string solver = "full";
  std::string linear = "gepp";          // full Newton's inner solve
  nonlinear::NewtonOptions newton;      // every Newton (and GSL's stop tests)
  // The residual tolerance is relative to the mechanism's size (its longest link): the solver tests
  // ||Phi||_inf <= residual_tolerance * size, so a linkage's verdicts do not depend on its units.
  // False: absolute, in the file's length units (to compare with a hand-coded model of one size).
  bool tolerance_relative_to_size = true;
};

// One solve: the unknowns, how it ended, and (when it did not converge) the block that failed.
struct LinkageSolution {
  Eigen::VectorXd q;
  nonlinear::NewtonCounts outcome;
  int failed_block = -1;  // index into blocks(), for sequential and analytic; -1 otherwise
};

class LinkageSolver {
 public:
  // Solves the reference pose and reads the branch from it. Throws LinkageFileError "the
  // reference pose does not assemble" (naming the driver's value and what Newton reached) when
  // damped Newton from the rough positions does not converge; std::invalid_argument for an
  // unknown solver or linear method, or analytic on a model with a Newton block.
  LinkageSolver(const LinkageModel& model, LinkageSolverOptions options);
  LinkageSolver(const LinkageModel&&, LinkageSolverOptions) = delete;  // it keeps a reference: model must outlive it

  const LinkageModel& model() const { return model_; }
  const std::vector<LinkageBlock>& blocks() const { return blocks_; }
  // The options in force: residual_tolerance is absolute here (scaled by size() when relative).
  const LinkageSolverOptions& options() const { return options_; }
  // The mechanism's size: its longest link (crank included).
  double size() const { return size_; }
  // The reference pose's unknowns and the driver there (model units).
  const Eigen::VectorXd& reference() const { return reference_; }
  double reference_driver() const { return reference_driver_; }
  // +1 / -1 per block: the side of each dyad, the sign of det J of a Newton block; 0 for explicit.
  const std::vector<int>& reference_signature() const { return reference_signature_; }

  // Solves at driver value t (model units) from q0.
  LinkageSolution solve(double t, const Eigen::VectorXd& q0) const;
  // The closed form of every closed-form block, in order; of a dyad's two solutions, the one nearer
  // the joint's place in q0 (a continuation: q0 is the previous pose, or its prediction). A Newton
  // block makes it fail with that block. Never throws.
  LinkageSolution closed_form(double t, const Eigen::VectorXd& q0) const;

  // The branch signature of a pose (see reference_signature).
  std::vector<int> signature(const Eigen::VectorXd& q, double t) const;
  // The transmission angle of each dyad block in degrees (the angle between its two links at the
  // joint, or between the link and the normal to the slider's line); NaN for other blocks.
  std::vector<double> transmission_angles(const Eigen::VectorXd& q) const;
  // How far each dyad is from its limit (0 at it, negative past it): min(d - |r1 - r2|, r1 + r2 - d)
  // for circle-circle, r - (distance of the centre from the line) for circle-line; NaN otherwise.
  std::vector<double> dyad_margins(const Eigen::VectorXd& q) const;

 private:
  LinkageSolution solve_full(double t, const Eigen::VectorXd& q0) const;
  LinkageSolution solve_sequential(double t, const Eigen::VectorXd& q0) const;
  LinkageSolution solve_gsl(double t, const Eigen::VectorXd& q0) const;

  const LinkageModel& model_;
  LinkageSolverOptions options_;
  std::vector<LinkageBlock> blocks_;
  Eigen::VectorXd reference_;
  double reference_driver_ = 0.0;
  std::vector<int> reference_signature_;
  double size_ = 1.0;
};

}  // namespace numlab::mechanisms
