#pragma once
// The model numlab derives from a linkage description (docs/linkage-files.md, "The derived model").
//
// Formulation: joint coordinates. The unknowns are the x and y of every moving joint; each
// description item becomes constraints on them:
//
//   link i-j of length L          1 row   (|p_i - p_j|^2 - L^2) / (2 L) = 0   (in length units near a root)
//   body with joints b0, b1, c... 1 row   the distance b0-b1 (unless the crank drives it)
//                                 2 rows  per further joint c: p_c - p_b0 - a (p_b1 - p_b0) - b perp(p_b1 - p_b0) = 0
//                                         with (a, b) from the local coordinates: c stays where the body
//                                         puts it, never in its mirror image, so a body cannot flip
//   slider of joint j             1 row   u x (p_j - P) = 0, the joint on the line through P along u
//   slider of A on line B-C       1 row   ((p_C - p_B) x (p_A - p_B)) / |p_C - p_B| - e = 0, e the slot's offset
//   crank about pivot O           2 rows  p_A - p_O - r (cos t, sin t) = 0, t = theta + offset
//   slider driver                 1 row   u . (p_j - P) - s = 0
//   actuator P-Q                  1 row   |p_P - p_Q| - s = 0
//   motor B-A-C                   1 row   l ((u x v) cos t - (u . v) sin t) / (|u| |v|) = 0, u = p_B - p_A,
//                                         v = p_C - p_A, l = |AC| (so the row is in length units)
//
// The crank replaces the distance O-A of its link or body (the two rows imply it). A model is
// square exactly when the mobility is one (linkage_structure.hpp checks that first).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms {

enum class ConstraintKind { distance, body_point, slider_line, crank, slider_travel, slider_on_line, actuator, motor };

// One constraint: 1 or 2 rows of the system, on up to three joints.
struct Constraint {
  ConstraintKind kind = ConstraintKind::distance;
  std::array<int, 3> joints{-1, -1, -1};  // distance: i, j; body_point: b0, b1, c; slider_line and
                                          // slider_travel: j; crank: pivot, joint; slider_on_line: A, B, C;
                                          // actuator: P, Q; motor: A (pivot), B (from), C (joint)
  double length = 0.0;                    // distance: L; crank: r; motor: l, the row's length scale;
                                          // actuator: its reference length (the scale of its zero length)
  Eigen::Vector2d coefficients = Eigen::Vector2d::Zero();  // body_point: (a, b)
  Eigen::Vector2d point = Eigen::Vector2d::Zero();         // slider: P
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();    // slider: u (unit)
  double offset = 0.0;                    // crank: radians added to the driver's angle; slider_on_line: e
  std::string name;                       // for messages and --explain: "link O-A", "body coupler: P"
  int body = -1;                          // the [[body]] whose rows these are (index), or -1
  // The second driver's constraint (crank, slider_travel or actuator) holds its own value instead of
  // the swept t: `held_value` in model units (radians or length); a held crank's unit direction
  // (cos, sin)(held_value + offset) is kept in `direction`.
  bool held = false;
  double held_value = 0.0;
  SourcePlace place;                      // where the file states the item it comes from

  int rows() const { return kind == ConstraintKind::body_point || kind == ConstraintKind::crank ? 2 : 1; }
};

// Joint positions: one per joint of the description (ground joints at their fixed place).
using JointPositions = std::vector<Eigen::Vector2d>;

class LinkageModel {
 public:
  // Derives the constraints. Throws LinkageFileError when the description is not a mechanism with
  // one degree of freedom (linkage_structure.hpp: mobility, then structural rank).
  explicit LinkageModel(LinkageDescription description);
  // The same with every body's base pair given (indices into its joints, one pair per body; empty:
  // the first two), not chosen from the structure, and no check (body_base_pairs.hpp tries pairs).
  LinkageModel(LinkageDescription description, std::vector<std::array<int, 2>> base_pairs);

  const LinkageDescription& description() const { return description_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }
  const std::vector<std::array<int, 2>>& base_pairs() const { return base_pairs_; }
  int unknown_count() const { return static_cast<int>(moving_.size()) * 2; }
  int equation_count() const { return equation_count_; }
  // Moving joints in unknown order: unknowns 2k, 2k+1 are x, y of joint moving()[k].
  const std::vector<int>& moving() const { return moving_; }
  // The unknown index of joint j's x (y is the next one), or -1 for a ground joint.
  int column_of(int joint) const { return column_[static_cast<std::size_t>(joint)]; }
  // The first row of constraint k.
  int first_row(int k) const { return first_row_[static_cast<std::size_t>(k)]; }
  // Names of rows and columns: "link O-A", "x_B".
  std::string row_name(int row) const;
  std::string column_name(int column) const;

  // The driver's value in the model's units: radians for a crank or motor, length for a slider or
  // actuator. `value` is what the user gives: degrees for a crank or motor, length otherwise.
  double driver_from_user(double value) const;
  double driver_to_user(double value) const;
  // Whether the driver is an angle (a crank or a motor: degrees, periodic), not a length.
  bool crank_driven() const { return description_.driver.angle(); }
  DriverKind driver_kind() const { return description_.driver.kind; }

  // The second driver (a file with two, mobility 2): its value in the user's units (degrees for a
  // crank, length otherwise), held while the first driver sweeps; the file's reference until
  // hold_second_driver changes it. NaN when there is no second driver.
  bool has_second_driver() const { return description_.second_driver.has_value(); }
  double second_driver() const;
  void hold_second_driver(double user_value);
  // d Phi / d s for the second driver at `user_value` (degrees or length; NaN: the value held now):
  // nonzero only on its rows. With it the second driver's load is lambda . phi_s, as the first's is
  // lambda . Phi_t (linkage_statics.hpp).
  void second_driver_derivative(double user_value, Eigen::VectorXd& phi_s) const;

  // Positions <-> unknowns.
  JointPositions positions(const Eigen::VectorXd& q) const;
  Eigen::VectorXd unknowns(const JointPositions& positions) const;
  JointPositions rough_positions() const;  // the description's positions (reference pose)

  // Phi(q; t) and its Jacobian d Phi / d q, for the driver's value t (model units). J must be
  // unknown_count() square; only nonzeros are written (J is zeroed first).
  void residual(const Eigen::VectorXd& q, double t, Eigen::VectorXd& f) const;
  void jacobian(const Eigen::VectorXd& q, double t, Eigen::MatrixXd& J) const;
  // The same J as its entries (row, column, value), each structural entry once per constraint that
  // writes it (a sparse matrix sums duplicates): time and memory linear in the constraints.
  struct JacobianEntry {
    int row, column;
    double value;
  };
  void jacobian_entries(const Eigen::VectorXd& q, double t, std::vector<JacobianEntry>& entries) const;
  // d Phi / d t at (q, t) and the right-hand side of the acceleration equation,
  //   gamma = -(qdot' Phi_qq qdot + 2 Phi_qt qdot + Phi_tt)   (so that J qddot = gamma).
  void driver_derivative(const Eigen::VectorXd& q, double t, Eigen::VectorXd& phi_t) const;
  void acceleration_rhs(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, double t, Eigen::VectorXd& gamma) const;

  // Per joint, ground joints included: sum over rows r of lambda_r d Phi_r / d p_j (J^T lambda split
  // by joint, with the ground joints' partials too). `forces` must hold one entry per joint; it is
  // overwritten, and nothing is allocated (linkage_statics.hpp: the constraint forces).
  void multiplier_forces(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                         std::vector<Eigen::Vector2d>& forces) const;

  // The structural nonzero pattern of J: row r has column c when constraint r's joints include
  // c's joint (x and y together, so a joint's two unknowns always fall in one block).
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> pattern() const;

 private:
  void derive();
  template <typename Put>
  void for_each_partial(const Eigen::VectorXd& q, double t, Put put) const;
  void add(Constraint constraint);

  LinkageDescription description_;
  std::vector<std::array<int, 2>> base_pairs_;  // per body, or empty (the first two joints)
  std::vector<Constraint> constraints_;
  std::vector<int> moving_, column_, first_row_;
  std::vector<int> row_constraint_;  // constraint of each row
  int equation_count_ = 0;
};

}  // namespace numlab::mechanisms
