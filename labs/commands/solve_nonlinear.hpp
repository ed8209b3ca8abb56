#pragma once
// `numlab solve nonlinear`: one MGH test problem, hand-written Newton or a GSL type (docs/cli.md).

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <optional>
#include <string>

#include "cli/cli_common.hpp"

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
  std::string problem_;
  std::string method_;
  std::string linear_ = "gepp";
  std::string x0_;
  bool damped_ = false;
  std::optional<double> step_tolerance_;
};

// "1,-2.5,3e-4" as a vector of `expected` numbers; throws std::invalid_argument naming the problem.
Eigen::VectorXd parse_point(const std::string& text, int expected, const std::string& flag);

}  // namespace numlab::cli
