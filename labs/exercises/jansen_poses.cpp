#include "exercises/jansen_poses.hpp"

#include <stdexcept>

namespace numlab::exercises {

mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle) {
  const mechanisms::JansenLeg leg;
  const auto joints = leg.closed_form_joints(crank_angle);
  if (!joints) throw std::logic_error("the Jansen leg's closed form failed (it assembles at every crank angle)");
  return mechanisms::JansenLeg::angles_of(*joints, mechanisms::JansenClosure::seed_estimates());
}

double jansen_links_sum() {
  const mechanisms::JansenLengths L;
  return L.crank + L.l1 + L.l2 + L.l3 + L.l4 + L.l5 + L.l6 + L.l7 + L.l8 + L.a + L.b;
}

std::string jansen_angle_name(int index) { return "theta" + std::to_string(index + 1); }

}  // namespace numlab::exercises

namespace numlab::exercises {

std::string jansen_equations_markdown() {
  return R"(### The model: seed 000's Jansen leg, 8 equations in theta1 ... theta8

Frame (as `numlab mechanism jansen`): crank pivot O at the origin, fixed joint P1 = (-b, -a) =
(-38, -7.8). The crank O-A has length li = 15 at `crank_angle` ti (radians, counter-clockwise
from +x). Every angle is the direction of a link from +x, in radians:

| angle | link | length | | angle | link | length |
| --- | --- | --- | --- | --- | --- | --- |
| theta1 | A->B | l1 = 50 | | theta5 | C->E | l5 = 39.4 |
| theta2 | P1->B | l2 = 41.5 | | theta6 | A->D | l6 = 61.9 |
| theta3 | B->C | l3 = 55.8 | | theta7 | P1->D | l7 = 39.3 |
| theta4 | P1->C | l4 = 40.1 | | theta8 | D->E | l8 = 36.7 |

With s_k = sin(theta_k), c_k = cos(theta_k), Y = li sin(ti) + a and X = li cos(ti) + b (the
crank tip A seen from P1), f has exactly these 8 entries (index 0 first):

    f[0] = Y + l1 s1 - l2 s2                      (B: O->A->B = P1->B, y)
    f[1] = X + l1 c1 - l2 c2                      (B, x)
    f[2] = Y + l1 s1 + l3 s3 - l4 s4              (C: O->A->B->C = P1->C, y)
    f[3] = X + l1 c1 + l3 c3 - l4 c4              (C, x)
    f[4] = Y + l6 s6 - l7 s7                      (D: O->A->D = P1->D, y)
    f[5] = X + l6 c6 - l7 c7                      (D, x)
    f[6] = Y + l1 s1 + l3 s3 + l5 s5 - l7 s7 - l8 s8   (E: O->A->B->C->E = P1->D->E, y)
    f[7] = X + l1 c1 + l3 c3 + l5 c5 - l7 c7 - l8 c8   (E, x)

J[i][k] = d f[i] / d theta_(k+1): d(l sin t)/dt = l cos t and d(l cos t)/dt = -l sin t. J is
block lower-triangular in the pairs (theta1, theta2), (theta3, theta4), (theta6, theta7),
(theta5, theta8).
)";
}

}  // namespace numlab::exercises
