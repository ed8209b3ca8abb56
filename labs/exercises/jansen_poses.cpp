#include "exercises/jansen_poses.hpp"

#include <stdexcept>

#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::exercises {

namespace {
mechanisms::JansenJoints closed_form_joints(double crank_angle) {
  const auto joints = mechanisms::JansenLeg().closed_form_joints(crank_angle);
  if (!joints) throw std::logic_error("the Jansen leg's closed form failed (it assembles at every crank angle)");
  return *joints;
}
}  // namespace

mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle) {
  return mechanisms::JansenLeg::angles_of(closed_form_joints(crank_angle), mechanisms::JansenClosure::seed_estimates());
}

Eigen::VectorXd jansen10_closed_form_angles(double crank_angle) {
  using mechanisms::JansenModel;
  return mechanisms::jansen_angles_of(JansenModel::ten_equations, closed_form_joints(crank_angle),
                                      mechanisms::jansen_seed_estimates(JansenModel::ten_equations, mechanisms::JansenLeg()));
}

double jansen_links_sum() {
  const mechanisms::JansenLengths L;
  return L.crank + L.l1 + L.l2 + L.l3 + L.l4 + L.l5 + L.l6 + L.l7 + L.l8 + L.a + L.b;
}

std::string jansen_angle_name(int index) { return "theta" + std::to_string(index + 1); }

}  // namespace numlab::exercises
