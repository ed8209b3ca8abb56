#pragma once
// `numlab mechanism mustang (--crank DEG | --sweep START:STOP:STEP)` (docs/cli.md): seed 003's
// roof linkage by continuation from the seed's branch, with its assembly limits.

#include <string>

#include "commands/common_options.hpp"

namespace numlab::cli {

struct MustangRequest {
  double start, stop, step;  // degrees; a single --crank is start = stop
  std::string solver, linear;
  const CommonOptions& common;
  std::string svg, animate;
  std::string html{};  // --html: the linkage page (inside --out)
};

// Prints the result (text, CSV or JSON) and returns the exit code: 0, or 1 when a limit (or a
// solver failure) stopped the sweep.
int run_mustang(const MustangRequest& request);

}  // namespace numlab::cli
