// LinkageSolver and LinkageSystem keep a reference to their model. With NUMLAB_PASS_TEMPORARY this
// file must not compile; without it, it must (check_ownership.cmake). Only compiled, never linked:
// the model comes from a function declared here.
#include "numlab/mechanisms/linkage/linkage_solver.hpp"

using namespace numlab::mechanisms;

LinkageModel read_model();

double probe() {
#ifdef NUMLAB_PASS_TEMPORARY
  const LinkageSolver solver(read_model(), LinkageSolverOptions{});
#else
  const LinkageModel model = read_model();
  const LinkageSolver solver(model, LinkageSolverOptions{});
#endif
  return solver.size();
}

int probe_system() {
#ifdef NUMLAB_PASS_TEMPORARY
  const LinkageSystem system(read_model(), 0.5);
#else
  const LinkageModel model = read_model();
  const LinkageSystem system(model, 0.5);
#endif
  return system.dimension();
}
