// SequentialNewton keeps references to its system and its blocks. With NUMLAB_PASS_TEMPORARY this
// file must not compile; without it, it must (check_ownership.cmake).
#include <vector>

#include "line_system.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

using numlab::nonlinear::AsDynamicSystem;
using numlab::nonlinear::Block;
using numlab::nonlinear::SequentialNewton;
using numlab::ownership::Line;

int probe() {
  const Line line;
  const std::vector<Block> blocks{{{0}, {0}}};
#ifdef NUMLAB_PASS_TEMPORARY
  SequentialNewton newton(AsDynamicSystem<Line>(line), blocks);
#else
  const AsDynamicSystem<Line> dynamic(line);
  SequentialNewton newton(dynamic, blocks);
#endif
  return newton.solve(Eigen::VectorXd::Zero(1)).iterations;
}
