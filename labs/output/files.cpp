#include "output/files.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

// "" when a file can be made in `folder`, else why not (strerror). Tried, not guessed from the mode
// bits: root ignores them, and a read-only file system or /proc refuses root too. The probe file is
// removed at once.
std::string cannot_make_files_in(const fs::path& folder) {
  std::string probe = (folder / ".numlab-write-probe-XXXXXX").string();
  const int descriptor = mkstemp(probe.data());
  if (descriptor < 0) return std::strerror(errno);
  ::close(descriptor);
  ::unlink(probe.c_str());
  return "";
}

// The folder a file at `path` would be written into, or the nearest of its parents that exists
// (the folders between are made then).
fs::path nearest_existing_folder(const fs::path& path) {
  std::error_code error;
  fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  while (!fs::exists(folder, error) && folder.has_parent_path() && folder.parent_path() != folder) {
    folder = folder.parent_path();
  }
  return folder;
}

}  // namespace

void ensure_directory(const std::string& path) {
  std::error_code error;
  if (path.empty()) throw std::invalid_argument("an output folder needs a name");
  fs::create_directories(path, error);
  if (error || !fs::is_directory(path)) throw std::invalid_argument("cannot create output folder '" + path + "'");
  const std::string refused = cannot_make_files_in(path);
  if (!refused.empty()) throw std::invalid_argument("the output folder '" + path + "' takes no new files (" + refused + ")");
}

namespace {

// Steps 1-2 of writing a file whole: `contents` in a unique temporary beside `path` (so the rename
// stays in one file system), with the permissions a new file gets; its name, or on any failure the
// temporary removed and std::invalid_argument naming `path` and the error.
std::string write_temporary(const std::string& path, const std::string& contents) {
  const fs::path target(path);
  std::error_code error;
  if (path.empty() || !target.has_filename()) throw std::invalid_argument("cannot write '" + path + "': no file name");
  if (fs::is_directory(target, error)) throw std::invalid_argument("cannot write '" + path + "': it is a folder");
  if (target.has_parent_path()) ensure_directory(target.parent_path().string());
  // 1. A unique temporary beside the target.
  std::string temporary = (target.parent_path() / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::invalid_argument("cannot write '" + path + "': " + std::strerror(errno));
  // 2. Write it whole (mkstemp makes it private: the mode a new file gets first); the first error kept.
  const mode_t mask = umask(0);
  umask(mask);
  int cause = fchmod(descriptor, 0666 & ~mask) == 0 ? 0 : errno;
  for (std::size_t done = 0; cause == 0 && done < contents.size();) {
    const ssize_t count = ::write(descriptor, contents.data() + done, contents.size() - done);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) cause = count < 0 ? errno : EIO;
    if (count > 0) done += static_cast<std::size_t>(count);
  }
  if (::close(descriptor) != 0 && cause == 0) cause = errno;
  if (cause == 0) return temporary;
  ::unlink(temporary.c_str());
  throw std::invalid_argument("cannot write '" + path + "': " + std::strerror(cause));
}

// Step 3: the temporary renamed into place, or removed and std::invalid_argument naming `path`.
void put_in_place(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) == 0) return;
  const int cause = errno;
  ::unlink(temporary.c_str());
  throw std::invalid_argument("cannot write '" + path + "': " + std::strerror(cause));
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& contents) {
  put_in_place(write_temporary(path, contents), path);
}

FileBatch::~FileBatch() {
  for (const Staged& file : staged_) ::unlink(file.temporary.c_str());
}

void FileBatch::add(const std::string& path, const std::string& contents) {
  staged_.push_back({write_temporary(path, contents), path});
}

void FileBatch::commit() {
  // Renamed in order; a rename that fails (rare: the disk was written already) removes the rest.
  while (!staged_.empty()) {
    const Staged file = staged_.front();
    staged_.erase(staged_.begin());
    put_in_place(file.temporary, file.path);
  }
}

void check_standard_output() {
  // 1. Flush what is buffered; a write that fails now leaves its errno.
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  int cause = errno;
  // 2. A write that failed earlier left the stream's error flags, not its errno: the likely causes
  // read from the file (at the file-size limit; no room left on its file system).
  if (flushed && std::ferror(stdout) == 0 && std::cout.good()) return;
  struct stat info {};
  struct rlimit limit {};
  struct statvfs room {};
  if (cause == 0 && ::fstat(STDOUT_FILENO, &info) == 0 && S_ISREG(info.st_mode) && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
      limit.rlim_cur != RLIM_INFINITY && static_cast<rlim_t>(info.st_size) >= limit.rlim_cur) {
    cause = EFBIG;
  } else if (cause == 0 && ::fstatvfs(STDOUT_FILENO, &room) == 0 && room.f_bavail == 0) {
    cause = ENOSPC;
  }
  std::error_code error;
  const fs::path file = fs::read_symlink("/proc/self/fd/1", error);
  const std::string named = error ? "the standard output" : "the standard output '" + file.string() + "'";
  throw std::invalid_argument("cannot write " + named + ": " + (cause != 0 ? std::strerror(cause) : "a write failed") +
                              "; what it holds is cut short");
}

void check_outputs(const std::vector<PlannedFile>& outputs, const std::vector<std::string>& inputs) {
  std::error_code error;
  std::vector<fs::path> seen;
  for (const PlannedFile& output : outputs) {
    const std::string named = output.flag + " '" + output.path + "'";
    if (output.path.empty()) throw std::invalid_argument(output.flag + ": needs a file name");
    const fs::path path(output.path);
    if (fs::is_directory(path, error)) throw std::invalid_argument(named + " is a folder, not a file");
    if (path.has_parent_path() && fs::exists(path.parent_path(), error) && !fs::is_directory(path.parent_path(), error)) {
      throw std::invalid_argument(named + ": '" + path.parent_path().string() + "' is not a folder");
    }
    for (const std::string& input : inputs) {
      if (fs::exists(path, error) && fs::equivalent(path, input, error)) {
        throw std::invalid_argument(named + " is the input file '" + input + "'; numlab does not overwrite its input");
      }
    }
    const fs::path folder = nearest_existing_folder(path);
    if (fs::is_directory(folder, error)) {
      const std::string refused = cannot_make_files_in(folder);
      if (!refused.empty()) {
        throw std::invalid_argument(named + ": the folder '" + folder.string() + "' takes no new files (" + refused + ")");
      }
    }
    const fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) {
      throw std::invalid_argument(named + " is written twice by this command; give each output its own name");
    }
    seen.push_back(canonical);
  }
}

}  // namespace numlab::cli
