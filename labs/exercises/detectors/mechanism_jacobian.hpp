#pragma once
// Detectors for a student's f and J of a linkage closure (issue 29 §1; docs/exercises.md,
// "Diagnosis"): each tests one hypothesis about the cause of a mismatch against numlab's closure,
// evaluated wherever the hypothesis needs it (at the angles in degrees, with one angle for
// another, ...). Written for any closure: jansen-jacobian, jansen10-jacobian and the linkage
// exercise call them with numlab's f and J as a function of (driver angle, unknown angles).

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exercises/diagnosis.hpp"

namespace numlab::exercises {

// numlab's f and J of a closure at (driver angle, unknown angles), radians.
struct ClosureValues {
  Eigen::VectorXd f;
  Eigen::MatrixXd J;
};
using ClosureEvaluator = std::function<ClosureValues(double driver, const Eigen::VectorXd& theta)>;

// The evaluator of a numlab closure built from its driver angle and `arguments` (JansenClosure(crank),
// JansenClosure(crank, a variant's lengths), ...).
template <typename Closure, typename... Arguments>
ClosureEvaluator evaluator_of(Arguments... arguments) {
  return [arguments...](double driver, const Eigen::VectorXd& theta) {
    typename Closure::Vector f;
    typename Closure::Matrix J;
    Closure(driver, arguments...).residual_and_jacobian(typename Closure::Vector(theta), f, J);
    return ClosureValues{Eigen::VectorXd(f), Eigen::MatrixXd(J)};
  };
}

// The link whose direction is unknown k: J's column k is +-length sin or cos of theta_k.
struct ColumnLink {
  std::string name;  // "l6", "|r8| (P1->D)"
  double length = 0.0;
};

// What a failing J check holds: the student's J beside numlab's at one pose.
struct JacobianEvidence {
  Eigen::MatrixXd student;
  Eigen::MatrixXd reference;  // numlab's analytic J at (driver, theta)
  double driver = 0.0;
  Eigen::VectorXd theta;
  ClosureEvaluator evaluate;
  double tolerance = 0.0;                   // what rounding allows per entry
  std::function<std::string(int)> angle_name;  // "theta3" for column 2
  std::vector<ColumnLink> links;            // links[k] for column k; empty when not known
};

// The ranked detectors of J's causes (transposed_jacobian, degrees_for_radians, transposed_pair,
// mislabelled_entries (two columns' entries swapped, or whole rows or columns in another order),
// wrong_angle_column, derivative_sign, wrong_link, finite_difference_jacobian): the most specific
// that fires, or nothing.
std::vector<Detector> jacobian_detectors(const JacobianEvidence& evidence);
std::optional<Diagnosis> diagnose_jacobian(const JacobianEvidence& evidence);

// What a failing f check holds: the student's f beside numlab's at one pose.
struct ResidualEvidence {
  Eigen::VectorXd student;
  Eigen::VectorXd reference;
  double driver = 0.0;
  Eigen::VectorXd theta;
  ClosureEvaluator evaluate;
  double tolerance = 0.0;
  std::function<std::string(int)> angle_name = {};  // "theta3" for unknown 0; "angle k" when not given
};

// f_sign (f negated, or one angle's term with the opposite sign), degrees_for_radians,
// mislabelled_entries (f's entries in another order), then `extra` (an exercise's own, e.g. a
// swapped offset).
std::optional<Diagnosis> diagnose_residual(const ResidualEvidence& evidence, std::vector<Detector> extra = {});

// One way of mixing degrees and radians: the driver angle is multiplied by `driver_scale` and
// unknown k by angle_scales(k) before sin and cos (1 where the unit is right).
struct AngleUnits {
  double driver_scale = 1.0;
  Eigen::VectorXd angle_scales;
  std::string what;  // "the angles converted to degrees before sin and cos (sin(theta * 180/pi))"
};
// Every mix the detectors test, for `unknowns` angles: all angles (with the driver or without it),
// the driver alone (radians(crank) on a crank already in radians), and each angle alone, each both
// ways (180/pi and pi/180). `angle_name` names unknown k.
std::vector<AngleUnits> angle_units(int unknowns, const std::function<std::string(int)>& angle_name);
// numlab's f and J at the driver and angles as `units` mixes them (J without the chain factor).
ClosureValues evaluate_in(const AngleUnits& units, const ClosureEvaluator& evaluate, double driver,
                          const Eigen::VectorXd& theta);

// The digits of a length to 0.1, sorted: 67.5 and 65.7 give the same (a transposed typed constant).
std::string sorted_digits(double length);

}  // namespace numlab::exercises
