#pragma once
// The exercises, one factory each (each in its own NAME_exercise.cpp).

#include "exercises/exercise.hpp"

namespace numlab::exercises {

Exercise gepp_exercise();
Exercise gauss_seidel_exercise();
Exercise inverse2x2_exercise();
Exercise polyfit_exercise();
Exercise jansen_jacobian_exercise();
Exercise jansen10_jacobian_exercise();
Exercise jansen_newton_exercise();
Exercise mustang_newton_exercise();

}  // namespace numlab::exercises
