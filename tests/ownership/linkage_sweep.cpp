// The linkage sweep stepper keeps a reference to its solver. With NUMLAB_PASS_TEMPORARY this file
// must not compile; without it, it must (check_ownership.cmake). Only compiled, never linked.
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;

LinkageSolver make_solver();
const LinkageSolver& kept_solver();

int probe() {
#ifdef NUMLAB_PASS_TEMPORARY
  LinkageSweepStepper stepper(make_solver());
#else
  LinkageSweepStepper stepper(kept_solver());
#endif
  stepper.start(0.0, 10.0, 1.0);
  return stepper.iterations();
}
