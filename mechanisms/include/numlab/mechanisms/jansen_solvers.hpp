#pragma once
// Ways to find one pose of the Jansen leg, behind one interface, and the crank sweep over them.
//
// Solver names (design/cli.md): full (hand-written Newton, inner solver from `linear`: gepp,
// gauss-seidel, gsl-lu, eigen-lu), sequential (block by block: seed 000's four 2x2 blocks with the
// closed-form inverse; seed 001's five, found from the pattern), analytic (circle intersections),
// gsl-<type> (GSL's multiroot types).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

enum class JansenModel { eight_equations, ten_equations };  // seed 000, seed 001

struct PoseOutcome {
  Status status = Status::converged;
  int iterations = 0;
  double residual_inf = 0.0;
};

class JansenPoseSolver {
 public:
  virtual ~JansenPoseSolver() = default;
  // Solves the closure at `crank_angle` (radians), starting from `angles`, which it overwrites.
  virtual PoseOutcome solve(double crank_angle, Eigen::VectorXd& angles) = 0;
};

// The unknowns' names: theta1 ... theta8, or theta3 ... theta12.
std::vector<std::string> jansen_angle_names(JansenModel model);

// Joints of either model's angles.
JansenJoints jansen_joints(JansenModel model, const JansenLeg& leg, double crank_angle, const Eigen::VectorXd& angles);

// The model's angles for given joints, each within pi of `near`.
Eigen::VectorXd jansen_angles_of(JansenModel model, const JansenJoints& joints, const Eigen::VectorXd& near);

// The start of every sweep: seed 000's estimates at theta_i = 1.57 rad (for the 10-equation
// model, the same estimates converted through the joints they describe).
Eigen::VectorXd jansen_seed_estimates(JansenModel model, const JansenLeg& leg);

const std::vector<std::string>& jansen_solver_names();

// Throws std::invalid_argument for an unknown solver or linear method.
std::unique_ptr<JansenPoseSolver> make_jansen_solver(JansenModel model, const std::string& solver,
                                                     const std::string& linear, const nonlinear::NewtonOptions& options);

struct JansenPose {
  double crank_deg = 0.0;
  Eigen::VectorXd angles;
  JansenJoints joints;
  PoseOutcome outcome;
  double closed_form_distance = 0.0;  // max over joints of |joint - closed-form joint|
  double length_error = 0.0;          // worst link-length error
};

struct JansenSweep {
  std::vector<JansenPose> poses;  // the requested angles that were solved, in order
  Status status = Status::converged;
  int step_halvings = 0;           // how often a failed step was halved
  int walk_in_poses = 0;           // poses solved to walk from 1.57 rad to the first angle
  double worst_closed_form_distance = 0.0;
  double worst_length_error = 0.0;
  bool orientation_kept = true;    // the rigid triangles never flipped
};

// The solved angles of a sweep and nothing derived from them: what `numlab bench jansen` times.
struct JansenSweepAngles {
  Eigen::MatrixXd angles;           // column i: the angles of pose i (only the first outcomes.size() are solved)
  std::vector<double> crank_deg;    // the crank angle of each solved pose
  std::vector<PoseOutcome> outcomes;
  Status status = Status::converged;
  int step_halvings = 0;
  int walk_in_poses = 0;
};

// Solves start, start + step, ... up to stop (degrees), each pose starting from a prediction
// extrapolated from the poses before. The sweep begins with seed 000's estimates at 1.57 rad and,
// if `start` is elsewhere, first walks there in steps no larger than `step`. A failed step is
// halved (up to 20 times) before the sweep stops with that status.
JansenSweepAngles solve_crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                                    double step_deg);

// solve_crank_sweep(), then each pose's joints and its checks against the closed form.
JansenSweep crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                        double step_deg);

}  // namespace numlab::mechanisms
