#pragma once
// The mathematics of benchmarking profiles, as pure functions on a table of costs.
//
// costs[p][s] is what solver s spent on problem p (a time, or function evaluations) when it solved
// p, and +infinity when it did not.
//
// Dolan & Moré, "Benchmarking optimization software with performance profiles" (Math. Prog. 91,
// 2002):
//   1. the performance ratio  r_{p,s} = t_{p,s} / min_s t_{p,s}  (+infinity when s failed on p, or
//      when no solver solved p);
//   2. the profile  rho_s(tau) = |{p : r_{p,s} <= tau}| / |P|,  the fraction of problems that s
//      solves within a factor tau of the best solver. rho_s(1) is how often s is the fastest;
//      rho_s(tau) for large tau is how often s solves at all.
//
// Moré & Wild, "Benchmarking derivative-free optimization algorithms" (SIAM J. Optim. 20, 2009):
//   3. the data profile  d_s(kappa) = |{p : t_{p,s} <= kappa (n_p + 1)}| / |P|,  with t_{p,s} in
//      function evaluations and n_p the problem's number of unknowns: the fraction of problems s
//      solves within kappa "simplex gradients" (n + 1 evaluations each).

#include <limits>
#include <vector>

namespace numlab::cli {

using CostTable = std::vector<std::vector<double>>;  // [problem][solver]; +infinity = not solved
inline constexpr double not_solved = std::numeric_limits<double>::infinity();  // the cost of a failed run

// r_{p,s}: same shape as costs. Throws std::invalid_argument for rows of different lengths or a
// cost that is negative or NaN.
CostTable performance_ratios(const CostTable& costs);

// rho_s(tau) from the ratios: the fraction of rows whose ratio for solver s is <= tau (0 for no rows).
double performance_profile(const CostTable& ratios, int solver, double tau);

// d_s(kappa): the fraction of problems whose cost for solver s is <= kappa (n_p + 1). `sizes[p]`
// is n_p. Throws std::invalid_argument when sizes and costs differ in length.
double data_profile(const CostTable& evaluations, const std::vector<int>& sizes, int solver, double kappa);

// The places where some solver's profile steps up: every finite ratio (or every finite
// evaluations / (n_p + 1)), sorted, without repeats. A profile is constant between them.
std::vector<double> ratio_breakpoints(const CostTable& ratios);
std::vector<double> data_breakpoints(const CostTable& evaluations, const std::vector<int>& sizes);

}  // namespace numlab::cli
