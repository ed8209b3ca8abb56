#pragma once
// The program's exit codes (docs/cli.md).

#include "numlab/status.hpp"

namespace numlab::cli {

// Exit codes of docs/cli.md: 0 the method succeeded, 1 it ran but did not succeed (or was stopped
// with q at a --step pause), 2 bad input.
constexpr int exit_success = 0;
constexpr int exit_method_failed = 1;
constexpr int exit_bad_input = 2;
int exit_code_for(Status status);

}  // namespace numlab::cli
