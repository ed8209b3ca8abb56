#pragma once
// `numlab models`: the linkage description files shipped with numlab (docs/linkage-files.md), each
// with its title and the model numlab derives from it. `numlab mechanism NAME` runs one by name.

#include <CLI/CLI.hpp>

#include "commands/common_options.hpp"

namespace numlab::cli {

class ModelsCommand {
 public:
  explicit ModelsCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
};

}  // namespace numlab::cli
