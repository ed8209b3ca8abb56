#include "cli/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

bool holds_nist_data(const fs::path& folder) {
  std::error_code error;
  return fs::is_regular_file(folder / "Wampler4.dat", error);
}

// PREFIX/share/numlab/nist for the executable at PREFIX/bin/numlab (Linux: /proc/self/exe).
std::optional<fs::path> installed_data_dir() {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  return executable.parent_path().parent_path() / "share" / "numlab" / "nist";
}

}  // namespace

std::string nist_data_dir() {
  std::vector<fs::path> candidates;
  if (const char* variable = std::getenv("NUMLAB_DATA_DIR"); variable != nullptr && *variable != '\0') {
    candidates.push_back(fs::path(variable) / "nist");
  }
  if (const auto installed = installed_data_dir()) candidates.push_back(*installed);
  candidates.emplace_back(NUMLAB_SOURCE_NIST_DIR);
  std::string looked_in;
  for (const fs::path& folder : candidates) {
    if (holds_nist_data(folder)) return folder.string();
    looked_in += (looked_in.empty() ? "" : ", ") + folder.string();
  }
  throw std::invalid_argument("cannot find the NIST data sets (looked in " + looked_in + ")");
}

}  // namespace numlab::cli
