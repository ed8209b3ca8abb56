#pragma once
// The files numlab writes: whole or not at all, in folders checked before any work.

#include <string>
#include <vector>

namespace numlab::cli {

// Creates the output folder (and parents) and tries making a file in it; throws
// std::invalid_argument naming it on failure (so a read-only folder is refused before any work).
void ensure_directory(const std::string& path);

// Writes a file whole or not at all: to a unique temporary in the same folder, then renamed into
// place. On any failure the temporary is removed and std::invalid_argument names the file.
void write_file_atomically(const std::string& path, const std::string& contents);

// Several files written together, all of them whole or none: add() writes each to a temporary
// beside it at once (so a full disk shows before any is in place), commit() renames them all into
// place. A batch destroyed before commit() (an exception on the way) removes its temporaries.
class FileBatch {
 public:
  FileBatch() = default;
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  ~FileBatch();
  // Throws std::invalid_argument naming the file (the batch keeps what it staged before).
  void add(const std::string& path, const std::string& contents);
  void commit();

 private:
  struct Staged {
    std::string temporary, path;
  };
  std::vector<Staged> staged_;
};

// Flushes the standard output and throws std::invalid_argument naming it (its file, when it is one)
// and the error, when a write to it failed (a full disk, a file-size limit): what the shell's
// redirection holds is then cut short, and the exit code must say so. It cannot be made whole or
// absent: the shell opened it, maybe to append.
void check_standard_output();

// Checks, before any work, every file a command will write (`flag` names who asked for it):
// not empty, not an existing folder, in a folder that accepts files (the nearest existing one is
// tried), not the same file as an input, not twice among the outputs. Throws
// std::invalid_argument naming the first conflict.
struct PlannedFile {
  std::string path;
  std::string flag;
};
void check_outputs(const std::vector<PlannedFile>& outputs, const std::vector<std::string>& inputs);

}  // namespace numlab::cli
