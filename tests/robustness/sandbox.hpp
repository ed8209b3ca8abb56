#pragma once
// The folder a case runs in: the prepared input files, and snapshots of folders to compare
// before and after a run.

#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace numlab::robustness {

// Writes the prepared input files into `folder` (matrix files, CSV and NIST data sets, hostile
// bytes, a directory); `nist_dir` holds numlab's NIST data sets, copied whole or cut short.
void prepare_inputs(const std::string& folder, const std::string& nist_dir);

// Every entry under `folder` (not following links), by path relative to it: a content hash for a
// regular file, "dir" for a folder, "link -> target" for a link, "other" for the rest.
std::map<std::string, std::string> snapshot_tree(const std::string& folder);

// The names directly in `folder`.
std::set<std::string> list_names(const std::string& folder);

}  // namespace numlab::robustness
