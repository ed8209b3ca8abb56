// The C++ reference solution of `gauss-seidel`: the solve() of
// tests/exercises/batteries/linear/gauss_seidel_solution.hpp (also checked in-process there), served by the
// installed protocol loop.
#include "../../batteries/linear/gauss_seidel_solution.hpp"

int main() { return numlab::exercise::serve(gauss_seidel_solution::solve); }
