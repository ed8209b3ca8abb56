#pragma once
// numlab bench: its command line, checked, and the benchmark it runs (bench/).

#include <string>
#include <vector>

#include "commands/common_options.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace numlab::cli {

class BenchCommand {
 public:
  explicit BenchCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::string what_ = "all";
  std::string chart_;
  std::vector<int> sizes_ = {2, 8, 64, 256, 512, 1024};
  bool quick_ = false;
};

}  // namespace numlab::cli
