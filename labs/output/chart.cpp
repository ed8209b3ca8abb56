#include "output/chart.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "numlab/printable_text.hpp"

extern char** environ;

namespace numlab::cli {

namespace {

// The variable through which numlab points gnuplot at a temporary; a student's redraw leaves it unset.
constexpr const char* output_variable = "numlab_output";

// A gnuplot single-quoted string: a quote inside is written twice.
std::string gnuplot_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

ChartFiles chart_files(const std::string& chart_path) {
  const std::filesystem::path path(chart_path);
  const std::string extension = path.extension().string();
  if (extension != ".svg" && extension != ".png") {
    throw std::invalid_argument("--chart '" + chart_path + "': the file name must end in .svg or .png");
  }
  // The paths go into a gnuplot script between single quotes and into a shell command.
  // printable() escapes control bytes (C0, DEL, C1), bidi controls and invisible marks: a name it
  // changes would reach gnuplot's script, and the terminal, as something else.
  if (chart_path.find('\'') != std::string::npos || printable(chart_path) != chart_path) {
    throw std::invalid_argument("--chart '" + printable(chart_path) +
                                "': the file name must not contain quotes, control or invisible characters");
  }
  // The companions keep the chart's whole name, so they cannot take the name of a data file
  // beside it (mydata.svg's data is mydata.svg.data.csv, never mydata.csv).
  return {chart_path, chart_path + ".data.csv", chart_path + ".gp"};
}

std::vector<PlannedFile> planned_files(const ChartFiles& files, const std::string& flag) {
  return {{files.chart, flag}, {files.data, flag + " (its data)"}, {files.script, flag + " (its gnuplot script)"}};
}

std::string gnuplot_output_lines(const ChartFiles& files, int width, int height) {
  const bool svg = files.chart.ends_with(".svg");
  const std::string size = std::to_string(width) + "," + std::to_string(height);
  const std::string terminal = svg ? "set terminal svg size " + size + " dynamic enhanced font 'Helvetica,13' background rgb 'white'"
                                   : "set terminal pngcairo size " + size + " enhanced font 'Helvetica,11'";
  // numlab itself draws into a temporary beside the chart (numlab_output) and renames it into place.
  const std::string variable = output_variable;
  return terminal + "\nset output (exists('" + variable + "') ? " + variable + " : " +
         gnuplot_quoted(std::filesystem::absolute(files.chart).string()) + ")\n";
}

namespace {

// gnuplot's exit status and everything it printed (warnings included: kept off numlab's stdout, where
// they would break --format json; the first 4 KiB are kept to name a failure).
struct GnuplotRun {
  int wait_status = 0;
  std::string output;
};

std::string read_output(int descriptor) {
  std::string output;
  char buffer[4096];
  for (;;) {
    const ssize_t count = ::read(descriptor, buffer, sizeof buffer);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) return output;
    if (output.size() < sizeof buffer) output.append(buffer, std::min(static_cast<std::size_t>(count), sizeof buffer - output.size()));
  }
}

// Runs `gnuplot -e "numlab_output='TEMPORARY'" SCRIPT`, found on PATH, stdin from /dev/null, stdout
// and stderr into a pipe read here.
GnuplotRun run_gnuplot(const std::string& script, const std::string& temporary) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 1);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 2);
  std::string program = "gnuplot", flag = "-e", assignment = std::string(output_variable) + "=" + gnuplot_quoted(temporary);
  std::string script_argument = script;
  char* arguments[] = {program.data(), flag.data(), assignment.data(), script_argument.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, arguments, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  if (spawned != 0) {
    ::close(ends[0]);
    if (spawned == ENOENT) throw std::runtime_error("gnuplot is not installed (run: bash .ci/setup)");
    throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(spawned));
  }
  GnuplotRun run;
  run.output = read_output(ends[0]);
  ::close(ends[0]);
  while (::waitpid(pid, &run.wait_status, 0) < 0 && errno == EINTR) {
  }
  return run;
}

// Why gnuplot's run failed, or "" when it exited 0: its status and the first line it printed.
std::string failure_of(const GnuplotRun& run) {
  std::string how;
  if (WIFSIGNALED(run.wait_status)) how = "gnuplot was killed by signal " + std::to_string(WTERMSIG(run.wait_status));
  else if (WEXITSTATUS(run.wait_status) != 0) how = "gnuplot exited with status " + std::to_string(WEXITSTATUS(run.wait_status));
  else return "";
  std::string first_line = run.output.substr(0, run.output.find_first_of("\r\n"));
  first_line.erase(0, first_line.find_first_not_of(" \t"));
  return first_line.empty() ? how : how + ": " + first_line.substr(0, 160);
}

// Why the chart gnuplot wrote is not whole, or "" when it is: an SVG is not empty and ends with
// </svg>, a PNG ends with its IEND chunk.
std::string incompleteness_of(const std::string& path, bool svg) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "gnuplot wrote no chart";
  const std::streamoff size = in.tellg();
  if (size <= 0) return "gnuplot wrote an empty chart (is the disk full?)";
  const std::streamoff tail_size = std::min<std::streamoff>(size, 64);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.seekg(size - tail_size);
  in.read(tail.data(), tail_size);
  if (!in) return "cannot read back the chart gnuplot wrote";
  if (svg) {
    tail.erase(tail.find_last_not_of(" \t\r\n") + 1);
    return tail.ends_with("</svg>") ? "" : "gnuplot wrote a truncated SVG, without its closing </svg> (is the disk full?)";
  }
  static const std::string iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
  return tail.ends_with(iend) ? "" : "gnuplot wrote a truncated PNG, without its IEND chunk (is the disk full?)";
}

// A unique empty temporary beside the chart, with the permissions a new file gets.
std::string make_temporary_beside(const std::string& path) {
  const std::filesystem::path target(path);
  std::string temporary = (target.parent_path() / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  const int descriptor = mkstemp(temporary.data());
  if (descriptor < 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  const bool made = fchmod(descriptor, 0666 & ~mask) == 0;
  const int cause = errno;
  ::close(descriptor);
  if (!made) {
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(cause));
  }
  return temporary;
}

}  // namespace

void draw_chart(const ChartFiles& files, const std::string& csv, const std::string& script) {
  const std::filesystem::path folder = std::filesystem::path(files.chart).parent_path();
  if (!folder.empty()) ensure_directory(folder.string());
  write_file_atomically(files.data, csv);
  write_file_atomically(files.script, script);
  // gnuplot draws into a temporary beside the chart, renamed into place only when whole.
  const std::string temporary = make_temporary_beside(files.chart);
  std::string problem;
  try {
    problem = failure_of(run_gnuplot(files.script, std::filesystem::absolute(temporary).string()));
    if (problem.empty()) problem = incompleteness_of(temporary, files.chart.ends_with(".svg"));
    if (problem.empty() && std::rename(temporary.c_str(), files.chart.c_str()) != 0) problem = std::strerror(errno);
  } catch (const std::exception& error) {
    problem = error.what();
  }
  if (problem.empty()) return;
  ::unlink(temporary.c_str());
  throw std::runtime_error("cannot write '" + files.chart + "': " + problem + "; its data and script are in " +
                           files.data + " and " + files.script);
}

}  // namespace numlab::cli
