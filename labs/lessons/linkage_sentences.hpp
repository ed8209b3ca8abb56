#pragma once
// The linkage lab's sentences, each made from the numbers of the table printed beside it (see
// lab_sentences.hpp for the sentences the labs share). tests/labs/test_lab_linkage.cpp reads the
// tables back from the CSV files and checks every sentence against them.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "lessons/lab_sentences.hpp"

namespace numlab::cli {

// Step 1: what the model derived from a file is.
struct DerivedModelSummary {
  std::string file;          // "jansen.toml"
  int moving_joints = 0;
  int unknowns = 0;
  int equations = 0;
  int mobility = 0;
  std::vector<std::string> block_kinds;  // per block, as describe_block prints it: "dyad, closed form (circle-circle)"
};
// The unknowns and equations, the mobility, and the blocks counted: dyads in closed form, explicit
// blocks, Newton blocks; whether --solver analytic applies.
std::string derived_model_sentence(const DerivedModelSummary& model);

// Step 2: sequential Newton against full Newton on the derived model, from the measured times and
// iterations: the speed ratio, the iterations ratio, the cost of one iteration, and what a block
// iteration of the generic solve (nonlinear::BlockSystem on a model of `unknowns` unknowns) does.
std::string sequential_against_full_sentence(const SolverCost& sequential, const SolverCost& full, int unknowns);

// Step 3: one pose of the velocity and acceleration check.
struct DerivativeRow {
  double crank_deg;
  double velocity_difference;      // relative, against central differences of positions
  double acceleration_difference;  // relative, against the 7-point stencil
  double foot_speed;               // |v| of the output joint from J qdot = -Phi_t, per radian
  double seed_foot_speed;          // the same from an independent model (seed 000's rates)
};
std::string derivative_check_sentence(const std::vector<DerivativeRow>& rows, const std::string& joint);

// Step 4: a dyad approaching an assembly limit.
struct LimitApproachRow {
  double before_deg;   // distance below the limit found by bisection
  double mu_deg;       // the failing dyad's transmission angle
  double kappa;        // kappa_2(J) of the whole model
  double speed;        // |v| of the dyad's joint, per radian of crank
};
struct LimitApproach {
  double limit_deg;       // the last value that assembles
  double bracket_deg;     // the bisection's final bracket
  std::string block;      // "block 8 (P10 from (P7, P8): dyad, closed form (circle-circle))"
  std::string joint;      // the dyad's joint: "P10"
  std::vector<LimitApproachRow> rows;  // farthest first
};
// The limit and the block; mu falling and kappa rising over the rows; the exponents of d measured
// between the rows at `far` and `near` degrees before the limit (a fold gives -1/2 for kappa and the
// speed, +1/2 for mu).
std::string limit_approach_sentence(const LimitApproach& approach, double far, double near);
// log(value(near) / value(far)) / log(near / far): the power of the distance the rows show.
double measured_exponent(double far, double value_far, double near, double value_near);

// Step 5: a sweep through a crossing of two assembly branches.
struct CrossingPassage {
  double crossing_deg;                 // where the sweep reported the crossing
  double kappa_at, kappa_away;         // kappa_2(J) there, and at the sweep's first pose
  std::string joint;                   // the dyad's joint
  std::string side_before, side_after; // its side on the smooth branch
  Eigen::Vector2d before, after;       // the smooth branch's joint velocity, per radian, one step either side
  Eigen::Vector2d other_after;         // the other branch's, one step after
  double step_deg;
};
// Where the branches cross and how ill-conditioned J gets; the tangents either side (the incoming
// one continues on the smooth branch; the other branch leaves along another); the side change.
std::string crossing_sentence(const CrossingPassage& c);

// Step 7: the same leg modelled three ways.
struct ModelCost {
  std::string name;      // as the table prints it
  int unknowns = 0;
  int nonzeros = 0;      // Jacobian entries not zero at a pose
  double time_s = 0.0;   // per cycle, full Newton
  int iterations = 0;    // summed over the cycle
  double error = 0.0;    // worst joint distance from the closed form
};
// rows: the 10-equation model, the 8-equation model, the derived model, in that order.
std::string over_modelling_sentence(const std::vector<ModelCost>& rows);

// Step 8: the driving torque three ways at a few poses.
struct DrivingTorqueRow {
  double crank_deg;
  double multipliers;        // tau = lambda . Phi_t, J^T lambda = Q
  double virtual_work;       // -(sum F . v_J) per radian
  double potential;          // dV/dtheta, central difference of the loads' potential
  double scale;              // sum of |F . v_J|: the size the differences are read against
};
// How far the three agree (relative to the loads' terms), and the torque's range over the rows.
std::string driving_torque_sentence(const std::vector<DrivingTorqueRow>& rows);

// Step 9: a quick-return's output toggles and time ratio by root finding, beside the closed form.
struct QuickReturnSummary {
  std::string output;            // the output's name ("C": the ram)
  double slow_deg = 0.0;         // crank degrees of the slow stroke, between the toggles found by Brent
  double quick_deg = 0.0;        // of the quick stroke (360 - slow)
  double time_ratio = 0.0;       // slow / quick
  double closed_form_ratio = 0.0;
  double toggle_difference = 0.0;  // deg: the largest |Brent - closed form| over the two toggles
  double slow_from = 0.0, slow_to = 0.0;  // the output's travel where the slow stroke starts and ends
  std::string closed_form;       // the closed form in words: "sin theta = (y_O4 - y_O2) / r"
};
// The strokes in crank degrees, the ratio and what it means (the return that much faster at a
// steady crank speed), and how far the root finding is from the closed form.
std::string quick_return_sentence(const QuickReturnSummary& q);

}  // namespace numlab::cli
