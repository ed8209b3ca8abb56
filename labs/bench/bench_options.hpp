#pragma once
// What every benchmark takes from the command line: how to print, where files go, and Newton's
// residual tolerance when given (--format, --out, --tol).

#include <optional>
#include <string>

#include "output/format.hpp"

namespace numlab::cli {

struct BenchOptions {
  Format format = Format::text;
  std::string out_dir = "out";
  std::optional<double> tolerance;
};

}  // namespace numlab::cli
