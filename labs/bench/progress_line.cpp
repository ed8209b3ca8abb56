#include "bench/progress_line.hpp"

#include <unistd.h>

#include <iostream>

namespace numlab::cli {

void show_progress(const std::string& message) {
  if (isatty(STDERR_FILENO) != 0) std::cerr << "\r\033[K" << message << std::flush;
}

}  // namespace numlab::cli
