#pragma once
// The Jansen leg's exact poses for the exercises: seed 000's 8 angles from the closed form (circle
// intersections, jansen_leg.hpp) on the seed's branch, and what checks say about them.

#include <string>

#include "numlab/mechanisms/jansen_leg.hpp"

namespace numlab::exercises {

// theta1 ... theta8 of the closed-form pose at `crank_angle` (radians), on seed 000's branch.
mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle);

// theta3 ... theta12 of seed 001's 10-equation model at the same closed-form pose, each within pi
// of the model's start (jansen_seed_estimates).
Eigen::VectorXd jansen10_closed_form_angles(double crank_angle);

// The sum of the links of the 8-equation closure (15 + 50 + ... + 36.7): f's scale in messages.
double jansen_links_sum();

// "theta3" for index 2.
std::string jansen_angle_name(int index);

inline constexpr double degrees = 3.14159265358979323846 / 180.0;

}  // namespace numlab::exercises
