// The C++ reference solution of `gepp`: the solve() of
// tests/exercises/batteries/linear/gepp_solution.hpp (also checked in-process there), served by the
// installed protocol loop.
#include "../../batteries/linear/gepp_solution.hpp"

int main() { return numlab::exercise::serve(gepp_solution::solve); }
