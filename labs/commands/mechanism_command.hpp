#pragma once
// `numlab mechanism NAME (--crank DEG | --sweep START:STOP:STEP) [--solver S] [--linear L]` (docs/cli.md).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/cli_common.hpp"

namespace numlab::cli {

class MechanismCommand {
 public:
  explicit MechanismCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::string name_;
  std::optional<double> crank_;
  std::string sweep_;
  std::string solver_ = "full";
  std::string linear_ = "gepp";
  std::string svg_;
  std::string animate_;
  std::string beest_;
  double beest_seconds_ = 0.0;
  bool explain_ = false;
  bool check_jacobian_ = false;
  bool arrows_ = false;
  bool strict_ = false;
  std::string at_crossing_ = "smooth";
};

struct SweepRange {
  double start, stop, step;
};

// "START:STOP:STEP" in degrees; throws std::invalid_argument naming the problem.
SweepRange parse_sweep(const std::string& text);

}  // namespace numlab::cli
