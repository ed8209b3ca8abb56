#include "output/chart.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "cli/cli_common.hpp"

namespace numlab::cli {

ChartFiles chart_files(const std::string& chart_path) {
  const std::filesystem::path path(chart_path);
  const std::string extension = path.extension().string();
  if (extension != ".svg" && extension != ".png") {
    throw std::invalid_argument("--chart '" + chart_path + "': the file name must end in .svg or .png");
  }
  // The paths go into a gnuplot script between single quotes and into a shell command.
  if (std::any_of(chart_path.begin(), chart_path.end(), [](unsigned char c) { return c == '\'' || c < 0x20 || c == 0x7f; })) {
    throw std::invalid_argument("--chart '" + chart_path + "': the file name must not contain quotes or control characters");
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
  return terminal + "\nset output '" + std::filesystem::absolute(files.chart).string() + "'\n";
}

void draw_chart(const ChartFiles& files, const std::string& csv, const std::string& script) {
  const std::filesystem::path folder = std::filesystem::path(files.chart).parent_path();
  if (!folder.empty()) ensure_directory(folder.string());
  write_file_atomically(files.data, csv);
  write_file_atomically(files.script, script);
  const std::string command = "gnuplot '" + files.script + "' 2>&1";
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    throw std::runtime_error("gnuplot is not installed (run: bash .ci/setup); data and script are in " + files.data +
                             " and " + files.script);
  }
  if (std::system(command.c_str()) != 0) throw std::runtime_error("gnuplot failed on " + files.script);
}

}  // namespace numlab::cli
