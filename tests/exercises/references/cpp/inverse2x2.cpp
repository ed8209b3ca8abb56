// The C++ reference solution of `inverse2x2`: the solve() of
// tests/exercises/batteries/linear/inverse2x2_solution.hpp (also checked in-process there), served by the
// installed protocol loop.
#include "../../batteries/linear/inverse2x2_solution.hpp"

int main() { return numlab::exercise::serve(inverse2x2_solution::solve); }
