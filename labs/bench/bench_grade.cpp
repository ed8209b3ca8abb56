#include "bench/bench_grade.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "output/exit_codes.hpp"

extern char** environ;

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

// tests/exercises/references/python/gepp.py, as it was at build time.
constexpr const char* gepp_reference =
#include "bench/gepp_reference.inc"
    ;

// `text` with `from` replaced by `to`, which must be there (the bench's mutants stay what they say).
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("bench grade: the reference changed; cannot make a mutant");
  return text.substr(0, at) + to + text.substr(at + from.size());
}

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("bench grade: cannot write " + path.string());
}

// Runs `words` (words[0] an absolute path) and waits for it; its exit status.
int run_and_wait(std::vector<std::string> words) {
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (const int failed = posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ); failed != 0)
    throw std::runtime_error(fmt::format("bench grade: cannot start numlab: {}", std::strerror(failed)));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

int run_grade_bench(const BenchOptions& common, bool quick) {
  (void)common;
  const int count = quick ? 30 : 300;
  const std::string reference = gepp_reference;
  const std::string no_pivoting = replaced(
      reference, "p = k + int(np.argmax(np.abs(a[k:, k])))  # the largest |a_pk|, the first on a tie", "p = k");
  const std::string swap_without_b = replaced(reference, "        b[[k, p]] = b[[p, k]]\n", "");

  const char* tmpdir = std::getenv("TMPDIR");
  std::string folder = (fs::path(tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp") / "numlab-bench-grade-XXXXXX").string();
  if (mkdtemp(folder.data()) == nullptr) throw std::runtime_error("bench grade: cannot make a temporary folder");
  const fs::path root(folder);
  int expected_passes = 0;
  for (int k = 0; k < count; ++k) {
    const bool mutant = k % 10 == 9;
    expected_passes += mutant ? 0 : 1;
    write_text(root / "submissions" / fmt::format("student{:03}", k) / "solution.py",
               !mutant ? reference : (k / 10) % 2 == 0 ? no_pivoting : swap_without_b);
  }
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const auto start = std::chrono::steady_clock::now();
  const int status = run_and_wait({self.string(), "exercise", "grade", "gepp", "--submissions",
                                   (root / "submissions").string(), "--out", (root / "out").string()});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The verdicts: each reference passes every check, each mutant fails one.
  int passes = 0;
  int rows = 0;
  std::ifstream gradebook(root / "out" / "gradebook.csv");
  std::string line;
  std::getline(gradebook, line);  // the header
  while (std::getline(gradebook, line)) {
    ++rows;
    std::istringstream fields(line);
    std::string student, exercise, variant, passed, total;
    std::getline(fields, student, ',');
    std::getline(fields, exercise, ',');
    std::getline(fields, variant, ',');
    std::getline(fields, passed, ',');
    std::getline(fields, total, ',');
    const bool all = passed == total && !total.empty() && total != "0";
    const int k = std::atoi(student.c_str() + 7);
    if (all) ++passes;
    if (all == (k % 10 == 9)) std::cout << "bench grade: unexpected verdict for " << student << ": " << line << '\n';
  }
  const bool right = rows == count && passes == expected_passes && WIFEXITED(status) && WEXITSTATUS(status) == 1;
  std::cout << fmt::format(
      "bench grade: {} Python GEPP submissions ({} copies of the reference, {} mutants) graded by numlab exercise "
      "grade on {} jobs in {:.1f} s: {:.3f} s per submission ({:.3f} s per submission and core); {} pass every "
      "check{}\n",
      count, expected_passes, count - expected_passes, jobs, seconds, seconds / count, seconds * jobs / count, passes,
      right ? ", as expected" : fmt::format(", {} expected (rows {}, exit status {})", expected_passes, rows, status));
  if (!quick)
    std::cout << fmt::format("bench grade: goal 300 submissions in under 60 s: {}\n", seconds < 60.0 ? "met" : "NOT met");
  std::error_code ignored;
  fs::remove_all(root, ignored);
  return right ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
