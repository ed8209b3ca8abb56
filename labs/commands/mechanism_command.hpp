#pragma once
// `numlab mechanism NAME (--crank DEG | --sweep START:STOP:STEP) [--solver S] [--linear L]` (docs/cli.md).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands/common_options.hpp"

namespace numlab::cli {

struct SweepRange {
  double start, stop, step;
};

class MechanismCommand {
 public:
  explicit MechanismCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  // The files --svg, --animate, --beest, --html and --chart name, inside --out (empty: not asked for).
  struct OutputPaths {
    std::string svg, animate, beest, html;
    std::string chart;  // --chart's
  };
  std::string linkage_file() const;
  void check_flags(const CommonOptions& common, bool from_file) const;
  int explain(const CommonOptions& common, const std::string& file) const;
  int analyse(const CommonOptions& common, const std::string& file) const;
  OutputPaths checked_outputs(const CommonOptions& common, const std::string& file) const;
  // The one sweep interface: a description file or shipped model, the Mustang, the Jansen leg
  // (`file` is the description file, empty for the built-in linkages).
  using SweepLinkage = int (MechanismCommand::*)(const CommonOptions& common, const SweepRange& range,
                                                 const OutputPaths& paths, const std::string& file) const;
  int sweep_file(const CommonOptions& common, const SweepRange& range, const OutputPaths& paths,
                 const std::string& file) const;
  int sweep_mustang(const CommonOptions& common, const SweepRange& range, const OutputPaths& paths,
                    const std::string& file) const;
  int sweep_jansen(const CommonOptions& common, const SweepRange& range, const OutputPaths& paths,
                   const std::string& file) const;

  CLI::App* command_;
  CommonOptions common_;
  std::string name_;
  std::optional<double> crank_;
  std::string sweep_;
  std::string drivers_;  // --drivers: a path in driver space (a file with two drivers)
  std::string solver_ = "full";
  std::string linear_ = "gepp";
  std::string svg_;
  std::string animate_;
  std::string beest_;
  std::string html_;  // --html: the linkage page with a crank slider
  double beest_seconds_ = 0.0;
  bool explain_ = false;
  bool check_jacobian_ = false;
  bool arrows_ = false;
  bool strict_ = false;
  std::string at_crossing_ = "smooth";
  bool analyse_ = false;
  std::string output_;
  std::string speed_;
  std::optional<double> draw_at_;    // --draw-at: the pose --svg draws
  std::vector<std::string> paths_;   // --path: the joints whose paths the scenes highlight
  std::string chart_;                // --chart: the driving torque and mechanical advantage
};

// "START:STOP:STEP" in degrees; throws std::invalid_argument naming the problem.
SweepRange parse_sweep(const std::string& text);

}  // namespace numlab::cli
