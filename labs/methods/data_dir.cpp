#include "methods/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

// PREFIX/share/numlab/SUBFOLDER for the executable at PREFIX/bin/numlab (Linux: /proc/self/exe).
std::optional<fs::path> installed_data_dir(const std::string& subfolder) {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  return executable.parent_path().parent_path() / "share" / "numlab" / subfolder;
}

// The first of $NUMLAB_DATA_DIR/SUBFOLDER, the installed SUBFOLDER and `source_dir` that holds `marker`.
std::string find_data_dir(const std::string& subfolder, const std::string& marker, const std::string& source_dir,
                          const std::string& what) {
  std::vector<fs::path> candidates;
  if (const char* variable = std::getenv("NUMLAB_DATA_DIR"); variable != nullptr && *variable != '\0') {
    candidates.push_back(fs::path(variable) / subfolder);
  }
  if (const auto installed = installed_data_dir(subfolder)) candidates.push_back(*installed);
  candidates.emplace_back(source_dir);
  std::string looked_in;
  for (const fs::path& folder : candidates) {
    std::error_code error;
    if (fs::is_regular_file(folder / marker, error)) return folder.string();
    looked_in += (looked_in.empty() ? "" : ", ") + folder.string();
  }
  throw std::invalid_argument("cannot find " + what + " (looked in " + looked_in + ")");
}

}  // namespace

std::string nist_data_dir() {
  return find_data_dir("nist", "Wampler4.dat", NUMLAB_SOURCE_NIST_DIR, "the NIST data sets");
}

std::string examples_dir() {
  return find_data_dir("examples", "gepp_solution.py", NUMLAB_SOURCE_EXAMPLES_DIR, "the example solutions");
}

std::string models_dir() {
  return find_data_dir("models", "four-bar.toml", NUMLAB_SOURCE_MODELS_DIR, "the shipped linkage models");
}

}  // namespace numlab::cli
