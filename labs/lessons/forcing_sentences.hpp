#pragma once
// The newton lab's inexact-Newton step: what its table of forcing terms shows, said from its rows
// (outer Newton iterations against inner Gauss-Seidel sweeps). tests/labs checks it against the table.

#include <string>
#include <vector>

namespace numlab::cli {

// One row of the table: a forcing choice and how Newton with Gauss-Seidel ended under it.
struct ForcingRun {
  std::string forcing;  // as printed: "none", "constant:0.1", "eisenstat-walker"
  std::string status;   // as printed: "converged", "max_iterations", ...
  int iterations;       // outer Newton iterations
  int sweeps;           // inner Gauss-Seidel sweeps, summed over the iterations
  double residual;      // ||f||_inf at the end
};

// How many choices converged (status converged and ||f||_inf <= tolerance); which needs the fewest
// outer iterations and which the fewest inner sweeps, with the ratio of their sweeps; and how each
// choice that did not converge ended.
std::string forcing_tradeoff_sentence(const std::vector<ForcingRun>& runs, double tolerance);

}  // namespace numlab::cli
