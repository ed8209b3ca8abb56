// AsDynamicSystem keeps a reference to the fixed-size system it shows. With NUMLAB_PASS_TEMPORARY
// this file must not compile; without it, it must (check_ownership.cmake).
#include "line_system.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"

using numlab::nonlinear::AsDynamicSystem;
using numlab::ownership::Line;

int probe() {
#ifdef NUMLAB_PASS_TEMPORARY
  const AsDynamicSystem<Line> dynamic(Line{});
#else
  const Line line;
  const AsDynamicSystem<Line> dynamic(line);
#endif
  return dynamic.dimension();
}
