#pragma once
// `numlab solve nonlinear`: one MGH test problem, hand-written Newton or a GSL type (docs/cli.md).

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <optional>
#include <string>

#include "commands/common_options.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"

namespace numlab::cli {

class SolveNonlinearCommand {
 public:
  explicit SolveNonlinearCommand(CLI::App& solve);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::optional<std::string> forcing_;  // --forcing
  std::optional<int> reuse_jacobian_;   // --reuse-jacobian K: the chord method, J factored every K iterations
  std::string problem_;
  std::string method_;
  std::string linear_ = "gepp";
  std::string x0_;
  std::optional<int> start_factor_;  // --start 1|10|100: MINPACK's initpt factor
  std::optional<int> size_;          // --size N: the size of a variable-size problem
  bool damped_ = false;
  std::optional<double> step_tolerance_;
};

// Largest --size accepted: the Jacobian is dense (n^2 doubles, 8 MB at n = 1000).
inline constexpr int largest_cli_problem_size = 1000;

// --size and --start checked against the problem (bad input throws std::invalid_argument naming the
// flag), then the problem at that size and its start: MINPACK's initpt factor, --x0, or x0.
struct ChosenProblem {
  nonlinear::TestProblem problem;
  Eigen::VectorXd x0;
  std::string start;  // "1x0", "10x0", "100x0" or "given" (--x0)
};
ChosenProblem choose_problem(const std::string& name, std::optional<int> size, std::optional<int> start_factor,
                             const std::optional<std::string>& x0);

// "1,-2.5,3e-4" as a vector of `expected` numbers; throws std::invalid_argument naming the problem.
Eigen::VectorXd parse_point(const std::string& text, int expected, const std::string& flag);

}  // namespace numlab::cli
