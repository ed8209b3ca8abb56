#pragma once
// The benchmarks' one-line progress message on stderr, rewritten in place; only on a terminal, so
// that logs and pipes get nothing.

#include <string>

namespace numlab::cli {

// Replaces the progress line with `message` ("" clears it).
void show_progress(const std::string& message);

}  // namespace numlab::cli
