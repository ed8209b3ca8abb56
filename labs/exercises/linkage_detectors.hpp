#pragma once
// The linkage exercise's detectors (diagnosis.hpp): hypotheses about a wrong f, J or velocity of a
// derived linkage model, each tested against the student's replies at every pose a check sent.
// Written for the joint-coordinate model of any description file; the cause ids are the Jacobian
// exercises' (docs/exercises.md, "Diagnosis").

#include <Eigen/Dense>
#include <vector>

#include "exercises/diagnosis.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::exercises {

// One pose a closure check sent: the driver (model units, and as the request gave it), q, and the
// student's f or J beside numlab's.
struct LinkageClosureSample {
  double t = 0.0;            // model units (radians for a crank)
  double driver_user = 0.0;  // as sent: degrees for a crank
  Eigen::VectorXd q;
  Eigen::VectorXd f, f_expected;
  Eigen::MatrixXd J, J_expected;
};

// f's detectors: f_sign, degrees_for_radians, wrong_link. `tolerance` is the check's for one entry.
std::vector<Detector> linkage_f_detectors(const mechanisms::LinkageModel& model,
                                          const std::vector<LinkageClosureSample>& samples, double tolerance);

// J's detectors: transposed_jacobian, transposed_pair, derivative_sign, wrong_link,
// finite_difference_jacobian. `tolerance(k)` is the check's for one entry of sample k.
std::vector<Detector> linkage_J_detectors(const mechanisms::LinkageModel& model,
                                          const std::vector<LinkageClosureSample>& samples,
                                          const std::vector<double>& tolerances);

// A velocity over the sweep against numlab's: negated (derivative_sign), per degree instead of per
// radian (degrees_for_radians), from J^T (transposed_jacobian). `J` and `phi_t` at numlab's pose.
std::vector<Detector> linkage_velocity_detectors(const Eigen::VectorXd& got, const Eigen::VectorXd& expected,
                                                 const Eigen::MatrixXd& J, const Eigen::VectorXd& phi_t,
                                                 bool crank, double tolerance);

}  // namespace numlab::exercises
