// Newton keeps a reference to its system. With NUMLAB_PASS_TEMPORARY this file must not compile
// (the constructors taking a temporary are deleted); without it, it must (check_ownership.cmake).
#include "line_system.hpp"
#include "numlab/nonlinear/newton.hpp"

using numlab::nonlinear::Newton;
using numlab::ownership::Line;

double probe() {
#ifdef NUMLAB_PASS_TEMPORARY
  Newton<Line> newton(Line{});
#else
  const Line line;
  Newton<Line> newton(line);
#endif
  return newton.solve(numlab::nonlinear::Vector<1>::Zero()).x(0);
}

double probe_with_linear_step() {
  using Step = numlab::linalg::GaussElimination<1>;
#ifdef NUMLAB_PASS_TEMPORARY
  Newton<Line, Step> newton(Line{}, {}, Step{});
#else
  const Line line;
  Newton<Line, Step> newton(line, {}, Step{});
#endif
  return newton.solve(numlab::nonlinear::Vector<1>::Zero()).x(0);
}
