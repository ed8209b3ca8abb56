#pragma once
// What `numlab --version` prints: the project's version and the git commit the program was built
// from, both written at build time (labs/cli/write_build_info.cmake).

namespace numlab::cli {

// The project's version, "0.1.0" (CMakeLists.txt's project()).
const char* build_version();
// The commit's first 12 hex digits, followed by " with local changes" when the sources differed
// from it; "unknown" when the sources were not a git checkout or git was not installed.
const char* build_commit();

}  // namespace numlab::cli
