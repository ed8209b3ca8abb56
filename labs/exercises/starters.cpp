#include "exercises/starters.hpp"
#include "exercises/command_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace numlab::exercises {

namespace {

// The stub re-indented by `indent` as a function body, whatever indentation it came with.
std::string as_body(const std::string& stub, const std::string& indent) {
  std::vector<std::string> lines;
  std::istringstream in(stub);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  while (!lines.empty() && lines.back().find_first_not_of(" \t") == std::string::npos) lines.pop_back();
  std::size_t common = std::string::npos;
  for (const std::string& line : lines) {
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos) common = std::min(common, first);
  }
  std::string body;
  for (const std::string& line : lines) {
    const bool blank = line.find_first_not_of(' ') == std::string::npos;
    body += blank ? "\n" : indent + line.substr(common) + '\n';
  }
  return body;
}

std::string python_solution(const Exercise& exercise) {
  return fmt::format(R"(#!/usr/bin/env python3
"""numlab exercise {name}: your solution (the task is in TASK.md).

Write solve(request) below: it gets one request (a dict; matrices are lists of rows) and returns
the reply (a dict; numpy arrays are sent as lists). Raise an exception to say you cannot answer:
the checker shows its message as a failing check.

The loop under solve() speaks numlab's protocol: one JSON request per line on stdin, one JSON
reply per line on stdout. Do not print to stdout; print diagnostics to stderr
(print(..., file=sys.stderr)): the checker shows them beside the check.

Check with: {check}
"""
import json
import sys

import numpy as np


def solve(request):
{body}

def to_json(value):
    """numpy arrays and numbers as plain lists and numbers, for json.dumps."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"cannot send a {{type(value).__name__}} as JSON")


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = dict(solve(request))
            reply["id"] = request.get("id")
            text = json.dumps(reply, default=to_json)
        except Exception as error:  # your code raised: the checker reports a failing check
            text = json.dumps({{"id": request.get("id"), "error": f"{{type(error).__name__}}: {{error}}"}})
        print(text, flush=True)


if __name__ == "__main__":
    main()
)",
                     fmt::arg("name", exercise.name), fmt::arg("check", check_command(exercise, Language::python)),
                     fmt::arg("body", as_body(exercise.stubs.python, "    ")));
}

std::string cpp_cmakelists(const Exercise& exercise) {
  return fmt::format(R"(# numlab exercise {name}: your solution, built against an installed numlab (see TASK.md).
cmake_minimum_required(VERSION 3.16)
project(numlab_exercise_{target} LANGUAGES CXX)

find_package(numlab REQUIRED)

add_executable(solution solution.cpp)
target_link_libraries(solution PRIVATE numlab::exercise_protocol)
)",
                     fmt::arg("name", exercise.name), fmt::arg("target", [&] {
                       std::string target = exercise.name;
                       std::replace(target.begin(), target.end(), '-', '_');
                       return target;
                     }()));
}

std::string cpp_solution(const Exercise& exercise) {
  return fmt::format(R"(// numlab exercise {name}: your solution (the task is in TASK.md).
//
// Write solve(request): it gets one request and returns the reply. Throw an exception to say you
// cannot answer: the checker shows its what() as a failing check. numlab::exercise::serve() runs
// the protocol loop (one JSON request per line on stdin, one JSON reply per line on stdout).
// Do not write to std::cout; write diagnostics to std::cerr: the checker shows them beside the check.
//
// Check with: {check}

#include <cmath>
#include <numlab/exercise_protocol.hpp>
#include <stdexcept>

using nlohmann::json;
using numlab::exercise::Matrix;  // std::vector<std::vector<double>>: numlab::exercise::matrix(request["A"])
using numlab::exercise::Vector;  // std::vector<double>: numlab::exercise::vector(request["b"])

json solve(const json& request) {{
{body}}}

int main() {{ return numlab::exercise::serve(solve); }}
)",
                     fmt::arg("name", exercise.name), fmt::arg("check", check_command(exercise, Language::cpp)),
                     fmt::arg("body", as_body(exercise.stubs.cpp, "  ")));
}

std::string octave_solution(const Exercise& exercise) {
  return fmt::format(R"(% numlab exercise {name}: your solution (the task is in TASK.md). Needs Octave 7 or later.
%
% Write solve(request): it gets one request (a struct from jsondecode; a matrix given as a list of
% rows arrives as a matrix) and returns the reply (a struct). Call error(...) to say you cannot
% answer: the checker shows the message as a failing check. to_json below sends a vector (row or
% column) as a list and a matrix as a list of rows. A 1x1 value is sent as a number (a 1x1 struct
% as an object): a list that may have one entry (x when n = 1, a trace of one step) goes as a cell,
% num2cell(x) or num2cell(trace).
% The loop at the end speaks the protocol: one JSON request per line on stdin, one JSON reply per
% line on stdout. Do not print to stdout (end statements with ;); fprintf(stderr, ...) for
% diagnostics: the checker shows them beside the check.
%
% Check with: {check}
1;

function reply = solve(request)
{body}end

% The reply as JSON, every number with 17 significant digits (NaN and Inf as null): Octave 7's
% jsonencode writes numbers below about 1e-15 as 0, so it only quotes strings here.
function text = to_json(value)
  if isstruct(value) && isscalar(value)
    names = fieldnames(value);
    parts = cell(1, numel(names));
    for k = 1:numel(names)
      parts{{k}} = [jsonencode(names{{k}}), ':', to_json(value.(names{{k}}))];
    end
    text = ['{{', strjoin(parts, ','), '}}'];
  elseif isstruct(value) || iscell(value)
    if isstruct(value)
      value = num2cell(value);
    end
    text = ['[', strjoin(cellfun(@to_json, reshape(value, 1, []), 'UniformOutput', false), ','), ']'];
  elseif ischar(value)
    text = jsonencode(value);
  elseif islogical(value) && isscalar(value)
    text = 'false';
    if value
      text = 'true';
    end
  elseif isscalar(value)
    text = json_number(value);
  elseif isvector(value) || isempty(value)
    text = ['[', strjoin(arrayfun(@json_number, reshape(value, 1, []), 'UniformOutput', false), ','), ']'];
  else
    rows = arrayfun(@(i) to_json(value(i, :)), 1:size(value, 1), 'UniformOutput', false);
    text = ['[', strjoin(rows, ','), ']'];
  end
end

function text = json_number(v)
  text = 'null';
  if isfinite(v)
    text = sprintf('%.17g', double(v));
  end
end

% input('', 's') reads one line as soon as it arrives (fgetl(stdin) would wait for the pipe to
% fill or close); at the end of stdin it raises, and the loop ends.
while true
  try
    line = input('', 's');
  catch
    break;
  end
  if isempty(strtrim(line))
    continue;
  end
  request = jsondecode(line);
  try
    reply = solve(request);
    reply.id = request.id;
    text = to_json(reply);
  catch err
    text = to_json(struct('id', request.id, 'error', err.message));
  end
  fputs(stdout, [text, "\n"]);
  fflush(stdout);
end
)",
                     fmt::arg("name", exercise.name), fmt::arg("check", check_command(exercise, Language::octave)),
                     fmt::arg("body", as_body(exercise.stubs.octave, "  ")));
}

// What to write and what it needs, before the command.
std::string what_to_write(Language language) {
  switch (language) {
    case Language::python: return "Write `solve(request)` in `solution.py` (Python 3 with numpy).";
    case Language::cpp:
      return "Write `solve(request)` in `solution.cpp`. It builds against an installed numlab (its header "
             "`numlab/exercise_protocol.hpp` runs the protocol loop); the command below finds numlab's install "
             "prefix from the `numlab` on your PATH (PREFIX/bin/numlab).";
    case Language::octave:
      return "Write `solve(request)` in `solution.m` (Octave 7 or later: `apt-get install octave`).";
  }
  return "";
}

std::string how_to_check(const Exercise& exercise, Language language) {
  return fmt::format("{} Then, in this folder:\n\n```\n{}\n```\n", what_to_write(language),
                     check_command(exercise, language));
}

}  // namespace

Language parse_language(const std::string& name) {
  if (name == "python") return Language::python;
  if (name == "cpp") return Language::cpp;
  if (name == "octave") return Language::octave;
  throw std::invalid_argument("exercise init: --lang must be python, cpp or octave, not '" + name + "'");
}

std::string check_command(const Exercise& exercise, Language language) {
  std::string check = "numlab exercise check " + exercise.name + " ";
  for (const std::string& argument : exercise.arguments) check += argument + " ";
  check += "-- ";
  switch (language) {
    case Language::python: return check + "python3 solution.py";
    case Language::cpp:
      return "cmake -S . -B build -DCMAKE_PREFIX_PATH=\"$(dirname \"$(dirname \"$(command -v numlab)\")\")\" && "
             "cmake --build build && " +
             check + "build/solution";
    case Language::octave: return check + "octave-cli --no-gui --quiet solution.m";
  }
  return check;
}

namespace {

// The section of TASK.md that names a variant.
std::string variant_section(const Exercise& exercise, const Variant& variant) {
  const std::string more = exercise.variant_task ? exercise.variant_task(variant) : "";
  return fmt::format("\n## Your variant\n\nYour variant is `{}`: the checks send you the random matrices, data, "
                     "starts and crank angles of this variant (another ID gets others). Check with `--variant {}`, "
                     "as the command below does; `numlab exercise check {}` without it checks another set of "
                     "inputs.\n{}",
                     *variant.id(), shell_word(*variant.id()), exercise.name, more.empty() ? "" : "\n" + more);
}

}  // namespace

std::vector<StarterFile> starter_files(const Exercise& exercise, Language language, const Variant& variant) {
  if (variant.active()) {  // the check commands in the files say --variant ID; TASK.md names it
    Exercise varied = exercise;
    varied.arguments.insert(varied.arguments.end(), {"--variant", shell_word(*variant.id())});
    if (exercise.varied_task) varied.task = exercise.varied_task(variant);
    std::vector<StarterFile> files = starter_files(varied, language);
    std::string& task = files.front().contents;
    const std::size_t how = task.rfind("\n## How to check");
    task.insert(how == std::string::npos ? task.size() : how, variant_section(exercise, variant));
    return files;
  }
  std::string task = exercise.task;
  if (!task.empty() && task.back() != '\n') task += '\n';
  std::vector<StarterFile> files = {{"TASK.md", task + "\n## How to check\n\n" + how_to_check(exercise, language), false}};
  switch (language) {
    case Language::python: files.push_back({"solution.py", python_solution(exercise), true}); break;
    case Language::cpp:
      files.push_back({"CMakeLists.txt", cpp_cmakelists(exercise), false});
      files.push_back({"solution.cpp", cpp_solution(exercise), false});
      break;
    case Language::octave: files.push_back({"solution.m", octave_solution(exercise), false}); break;
  }
  return files;
}

void write_starter_files(const std::string& folder, const std::vector<StarterFile>& files) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw std::runtime_error("cannot create the folder " + folder + ": " + error.message());
  for (const StarterFile& file : files) {
    const fs::path path = fs::path(folder) / file.path;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << file.contents;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
    if (file.executable) {
      fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                      fs::perm_options::add, error);
      if (error) throw std::runtime_error("cannot make " + path.string() + " executable: " + error.message());
    }
  }
}

}  // namespace numlab::exercises
