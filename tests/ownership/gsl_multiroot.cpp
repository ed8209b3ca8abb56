// GslMultiroot keeps a reference to its system (GSL calls back into it). With
// NUMLAB_PASS_TEMPORARY this file must not compile; without it, it must (check_ownership.cmake).
#include "line_system.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"

using numlab::nonlinear::AsDynamicSystem;
using numlab::nonlinear::GslMultiroot;
using numlab::ownership::Line;

int probe() {
  const Line line;
#ifdef NUMLAB_PASS_TEMPORARY
  GslMultiroot gsl(AsDynamicSystem<Line>(line), "hybridsj");
#else
  const AsDynamicSystem<Line> dynamic(line);
  GslMultiroot gsl(dynamic, "hybridsj");
#endif
  return gsl.solve(Eigen::VectorXd::Zero(1)).iterations;
}
