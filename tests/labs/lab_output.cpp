#include "lab_output.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "../cli/run_numlab.hpp"

namespace numlab::test {

namespace {

// Every run of white space as one space.
std::string unwrapped(const std::string& text) {
  std::string flat;
  for (const char c : text) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (!space) flat += c;
    else if (!flat.empty() && flat.back() != ' ') flat += ' ';
  }
  return flat;
}

// One CSV line: cells split at commas outside double quotes ("" inside quotes is one quote).
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) cells.emplace_back();
    else cells.back() += c;
  }
  return cells;
}

}  // namespace

CsvRows LabOutput::table(const std::string& file) const {
  std::ifstream csv(folder + "/" + file);
  if (!csv) throw std::runtime_error("no table " + folder + "/" + file);
  CsvRows rows;
  for (std::string line; std::getline(csv, line);) rows.push_back(csv_cells(line));
  return rows;
}

LabOutput run_lab(const std::string& name) {
  const std::string folder = temporary_folder();
  if (!name.empty()) {
    const ProgramRun run = run_numlab("lab " + name + " --out " + folder);
    return {run.exit_code, unwrapped(run.out), folder + "/lab-" + name};
  }
  // No arguments: the main job writes under ./out, so it runs inside the temporary folder.
  const std::string command = "cd " + folder + " && " + std::string(NUMLAB_BINARY) + " </dev/null >stdout 2>stderr";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, unwrapped(read_all(folder + "/stdout")),
          folder + "/out/lab-jansen"};
}

double number(const std::string& cell) {
  try {
    return std::stod(cell);
  } catch (const std::exception&) {
    return std::nan("");
  }
}

std::size_t column(const CsvRows& rows, const std::string& header) {
  const auto at = std::find(rows.at(0).begin(), rows.at(0).end(), header);
  if (at == rows.at(0).end()) throw std::runtime_error("no column " + header);
  return static_cast<std::size_t>(at - rows.at(0).begin());
}

bool has_developer_talk(const std::string& text) {
  static const std::regex words(R"(\b(target|targets|Targets|NOT met|goal|requirement)\b)");
  return std::regex_search(text, words);
}

}  // namespace numlab::test
