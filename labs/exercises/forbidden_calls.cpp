// The forbidden library functions of each exercise (forbidden_calls.hpp). Each list is what the
// task forbids, as its TASK.md says under "Library functions"; test_forbidden_calls.cpp holds the
// two to each other.
#include "exercises/forbidden_calls.hpp"

#include <map>

namespace numlab::exercises {

namespace {

// A library solve, factorisation that solves, or inverse of a linear system (gepp, gauss-seidel).
const std::vector<std::string> python_linear_solvers = {
    "numpy.linalg:solve",        "numpy.linalg:inv",          "numpy.linalg:lstsq",       "numpy.linalg:pinv",
    "numpy.linalg:tensorsolve",  "numpy.linalg:tensorinv",    "numpy.linalg:qr",          "numpy.linalg:cholesky",
    "scipy.linalg:solve",        "scipy.linalg:solve_triangular", "scipy.linalg:solve_banded",
    "scipy.linalg:solveh_banded", "scipy.linalg:lu",          "scipy.linalg:lu_factor",   "scipy.linalg:lu_solve",
    "scipy.linalg:inv",          "scipy.linalg:lstsq",        "scipy.linalg:pinv",        "scipy.linalg:pinvh",
    "scipy.linalg:cho_factor",   "scipy.linalg:cho_solve",    "scipy.linalg:cholesky",    "scipy.linalg:qr",
    "scipy.sparse.linalg:spsolve", "scipy.sparse.linalg:splu"};
const std::vector<std::string> octave_linear_solvers = {"inv",     "pinv",     "lu",     "qr",   "chol",
                                                        "mldivide", "mrdivide", "linsolve", "lscov", "lsqnonneg"};

std::vector<std::string> joined(std::vector<std::string> first, const std::vector<std::string>& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

const std::map<std::string, ForbiddenCalls>& table() {
  static const ForbiddenCalls newton{
      "Write the Newton iteration yourself: a library solve of J dx = -f is allowed, a library nonlinear solver is not.",
      "this exercise asks for Newton's iteration by hand",
      {"scipy.optimize:fsolve", "scipy.optimize:root", "scipy.optimize:newton", "scipy.optimize:least_squares",
       "scipy.optimize:broyden1", "scipy.optimize:broyden2", "scipy.optimize:newton_krylov"},
      {"fsolve", "fminsearch", "fminunc"}};
  static const ForbiddenCalls jacobian{
      "J must be analytic: no library finite differences.",
      "this exercise asks for J differentiated by hand",
      {"scipy.optimize:approx_fprime", "scipy.differentiate:jacobian", "numdifftools:Jacobian"},
      {}};
  static const std::map<std::string, ForbiddenCalls> calls = {
      {"gepp",
       {"Use arrays for storage only: no library solver, LU or inverse.",
        "this exercise asks for elimination by hand", python_linear_solvers, octave_linear_solvers}},
      {"gauss-seidel",
       {"Sweep by hand, arrays for storage only: no library solver, factorisation or inverse.",
        "this exercise asks for Gauss-Seidel sweeps by hand",
        joined(python_linear_solvers, {"scipy.sparse.linalg:cg", "scipy.sparse.linalg:gmres",
                                       "scipy.sparse.linalg:bicgstab", "scipy.sparse.linalg:lsqr"}),
        joined(octave_linear_solvers, {"pcg", "gmres", "bicgstab"})}},
      {"inverse2x2",
       {"Invert by the closed form: no library inverse, determinant or solver.",
        "this exercise asks for the closed form by hand",
        {"numpy.linalg:inv", "numpy.linalg:det", "numpy.linalg:solve", "numpy.linalg:pinv", "numpy.linalg:lstsq",
         "numpy.linalg:tensorinv", "scipy.linalg:inv", "scipy.linalg:det", "scipy.linalg:solve", "scipy.linalg:pinv",
         "scipy.linalg:lu", "scipy.linalg:lu_factor", "scipy.linalg:lstsq"},
        {"inv", "pinv", "det", "lu", "mldivide", "mrdivide", "linsolve"}}},
      {"polyfit",
       {"Build the scaled Vandermonde matrix and solve it yourself: a library QR, SVD or least-squares solve is "
        "allowed, a library polynomial fit is not.",
        "this exercise asks you to build and solve the scaled Vandermonde least-squares problem yourself",
        {"numpy:polyfit", "numpy.ma:polyfit", "numpy.polynomial.polynomial:polyfit", "numpy.polynomial:Polynomial.fit"},
        {"polyfit"}}},
      {"jansen-newton", newton},
      {"mustang-newton", newton},
      {"jansen-jacobian", jacobian},
      {"jansen10-jacobian", jacobian},
  };
  return calls;
}

}  // namespace

const ForbiddenCalls& forbidden_calls(const std::string& exercise) {
  static const ForbiddenCalls none;
  const auto found = table().find(exercise);
  return found == table().end() ? none : found->second;
}

std::string python_call_name(const std::string& entry) {
  std::string name = entry;
  if (const std::size_t colon = name.find(':'); colon != std::string::npos) name[colon] = '.';
  return name;
}

}  // namespace numlab::exercises
