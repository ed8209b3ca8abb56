// The dogleg keeps a reference to its system. With NUMLAB_PASS_TEMPORARY this file must not
// compile; without it, it must (check_ownership.cmake).
#include "line_system.hpp"
#include "numlab/nonlinear/dogleg.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"

using numlab::nonlinear::AsDynamicSystem;
using numlab::nonlinear::Dogleg;
using numlab::ownership::Line;

int probe() {
  const Line line;
#ifdef NUMLAB_PASS_TEMPORARY
  Dogleg dogleg{AsDynamicSystem<Line>(line)};
#else
  const AsDynamicSystem<Line> dynamic(line);
  Dogleg dogleg(dynamic);
#endif
  return dogleg.solve(Eigen::VectorXd::Zero(1)).iterations;
}
