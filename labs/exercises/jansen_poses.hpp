#pragma once
// The Jansen leg's exact poses for the exercises: seed 000's 8 angles from the closed form (circle
// intersections, jansen_leg.hpp) on the seed's branch, and what checks say about them.

#include <string>

#include "numlab/mechanisms/jansen_leg.hpp"

namespace numlab::exercises {

// theta1 ... theta8 of the closed-form pose at `crank_angle` (radians), on seed 000's branch.
mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle);

// The sum of the links of the 8-equation closure (15 + 50 + ... + 36.7): f's scale in messages.
double jansen_links_sum();

// "theta3" for index 2.
std::string jansen_angle_name(int index);

inline constexpr double degrees = 3.14159265358979323846 / 180.0;

}  // namespace numlab::exercises

namespace numlab::exercises {
// The 8-equation model in Markdown (frame, lengths, f_1 ... f_8 in the order of the reply), for
// the tasks of jansen-jacobian and jansen-newton.
std::string jansen_equations_markdown();
}  // namespace numlab::exercises
