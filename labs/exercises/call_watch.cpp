#include "exercises/call_watch.hpp"

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <system_error>

namespace numlab::exercises {

namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw std::system_error(errno ? errno : EIO, std::generic_category(), "cannot write " + path.string());
}

// "NAME=VALUE" with `value` first and the inherited value after it, separated by ':'.
std::string prepended(const char* name, const std::string& value) {
  const char* inherited = std::getenv(name);
  if (inherited == nullptr || *inherited == '\0') return fmt::format("{}={}", name, value);
  return fmt::format("{}={}:{}", name, value, inherited);
}

}  // namespace

std::string call_log_path(const std::string& folder) { return (fs::path(folder) / "calls.log").string(); }

std::vector<std::string> install_call_watch(const std::string& folder, const ForbiddenCalls& calls) {
  std::vector<std::string> environment;
  if (calls.empty()) return environment;
  fs::create_directories(folder);
  environment.push_back("NUMLAB_CALL_LOG=" + call_log_path(folder));
  if (!calls.python.empty()) {
    const fs::path python = fs::path(folder) / "python";
    fs::create_directory(python);
    write_text(python / "sitecustomize.py", python_watch_script());
    std::string listed;
    for (const std::string& entry : calls.python) listed += entry + '\n';
    write_text(python / "forbidden.txt", listed);
    environment.push_back(prepended("PYTHONPATH", python.string()));
  }
  if (!calls.octave.empty()) {
    const fs::path octave = fs::path(folder) / "octave";
    fs::create_directories(octave / "support");
    fs::create_directories(octave / "wrappers");
    write_text(octave / "init.m", octave_watch_init(calls.octave));
    write_text(octave / "support" / "numlab_watched_call.m", octave_watch_helper());
    for (const std::string& function : calls.octave) {
      write_text(octave / "wrappers" / (function + ".m"), octave_watch_wrapper(function));
    }
    environment.push_back("OCTAVE_SITE_INITFILE=" + (octave / "init.m").string());
    // The site file init.m stands in for, which it runs in turn.
    if (const char* site = std::getenv("OCTAVE_SITE_INITFILE"); site != nullptr && *site != '\0') {
      environment.push_back(std::string("NUMLAB_OCTAVE_SITE_INITFILE=") + site);
    }
  }
  return environment;
}

LibraryCalls read_call_log(const std::string& log, std::uintmax_t& offset) {
  LibraryCalls calls;
  std::ifstream file(log, std::ios::binary);
  if (!file) return calls;
  file.seekg(static_cast<std::streamoff>(offset));
  std::string line;
  while (std::getline(file, line)) {
    if (file.eof()) break;  // a line still being written: read it next time
    offset += line.size() + 1;
    if (line == "+python" || line == "+octave") {
      calls.watched.insert(line.substr(1));
    } else if (!line.empty()) {
      ++calls.counts[line];
    }
  }
  return calls;
}

}  // namespace numlab::exercises
