#pragma once
// `numlab solve linear`: one linear system, any method, text/JSON/CSV (docs/cli.md).

#include <CLI/CLI.hpp>
#include <string>

#include "commands/common_options.hpp"

namespace numlab::cli {

class SolveLinearCommand {
 public:
  explicit SolveLinearCommand(CLI::App& solve);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::string method_;
  std::string generate_;
  std::string matrix_file_;
  std::string rhs_file_;
  unsigned seed_ = 1;
};

}  // namespace numlab::cli
