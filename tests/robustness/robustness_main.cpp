// numlab's command-line robustness test (docs/robustness.md): runs the rows of cases.tsv, each in a fresh
// folder of prepared input files, and checks what docs/cli.md promises for hostile input.
//
//   test_robustness [ID ...]     the named rows (all rows when none is named)
//
// NUMLAB_TIME_SCALE multiplies every time limit (the sanitizer build's default is 4).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "case_table.hpp"
#include "child_run.hpp"
#include "sandbox.hpp"
#include "verdict.hpp"

namespace fs = std::filesystem;
using namespace numlab::robustness;

namespace {

double time_scale() {
  const char* scale = std::getenv("NUMLAB_TIME_SCALE");
  return scale != nullptr && std::atof(scale) > 0 ? std::atof(scale) : NUMLAB_TIME_SCALE_DEFAULT;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

// Entries that appeared at the filesystem root during the run: each is a failure, and numlab's own
// output folders there are removed again (only those, and only new ones).
void judge_root(const std::set<std::string>& before, std::vector<std::string>& failures) {
  for (const std::string& name : list_names("/")) {
    if (before.count(name) != 0) continue;
    failures.push_back("wrote '/" + name + "' at the filesystem root");
    if (name.starts_with("lab-") || name.starts_with("bench-") || name == "out") fs::remove_all("/" + name);
  }
}

// Runs one row in a fresh folder; returns its broken promises.
std::vector<std::string> run_case(const Case& row) {
  // 1. A fresh folder: ROOT/up/box is the case's working folder, ROOT/io holds its output.
  std::string root = (fs::temp_directory_path() / "numlab-robust-XXXXXX").string();
  if (mkdtemp(root.data()) == nullptr) return {"mkdtemp failed"};
  const fs::path up = fs::path(root) / "up", box = up / "box", io = fs::path(root) / "io";
  fs::create_directories(box);
  fs::create_directories(io);
  prepare_inputs(box.string(), NUMLAB_NIST_DIR);

  // 2. Snapshots before the run: the folder, its parent, the filesystem root.
  const auto before = snapshot_tree(box.string());
  const auto root_before = list_names("/");

  // 3. Run numlab there, with the time limit.
  const double limit = row.seconds * time_scale();
  const ChildResult run = run_child(NUMLAB_BINARY, row.arguments, box.string(), (io / "out").string(),
                                    (io / "err").string(), limit, NUMLAB_CHILD_SANITIZED ? 0 : 4096);

  // 4. Its output, then the files it left.
  std::vector<std::string> failures = judge_run(row, run, limit, read_bytes(io / "out"), read_bytes(io / "err"));
  for (const std::string& failure : judge_files(row, run.exit_code, before, snapshot_tree(box.string()))) failures.push_back(failure);
  for (const std::string& name : list_names(up.string())) {
    if (name != "box") failures.push_back("wrote '" + name + "' in the parent folder");
  }
  judge_root(root_before, failures);
  fs::remove_all(root);
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  // Under AddressSanitizer no address-space cap (it reserves terabytes); instead ASan ends a child
  // that asks for more than 4 GB at once or holds more than 4 GB, with a report: the row fails.
  if (NUMLAB_CHILD_SANITIZED) {
    const char* asan = std::getenv("ASAN_OPTIONS");
    const std::string options = std::string(asan != nullptr ? asan : "") + ":max_allocation_size_mb=4096:hard_rss_limit_mb=4096";
    setenv("ASAN_OPTIONS", options.c_str(), 1);
  }
  try {
    const std::vector<Case> cases = read_cases(NUMLAB_ROBUSTNESS_CASES, NUMLAB_NIST_DIR);
    const std::set<std::string> wanted(argv + 1, argv + argc);
    int run = 0, failed = 0;
    for (const Case& row : cases) {
      if (!wanted.empty() && wanted.count(row.id) == 0) continue;
      ++run;
      const std::vector<std::string> failures = run_case(row);
      std::cout << (failures.empty() ? "PASS " : "FAIL ") << row.id << "  (" << row.note << ")\n";
      for (const std::string& failure : failures) std::cout << "     - " << failure << '\n';
      failed += failures.empty() ? 0 : 1;
    }
    if (run != static_cast<int>(wanted.size()) && !wanted.empty()) {
      std::cout << "some named rows are not in the table\n";
      return 1;
    }
    std::cout << run - failed << " of " << run << " cases passed\n";
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "test_robustness: " << error.what() << '\n';
    return 1;
  }
}
