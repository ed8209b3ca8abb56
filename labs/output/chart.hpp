#pragma once
// Charts drawn by gnuplot from a script written next to the data, so a student can open the CSV
// and the script, change them, and redraw by hand with `gnuplot FILE.gp`.

#include <string>
#include <vector>

#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"

namespace numlab::cli {

struct ChartFiles {
  std::string chart;   // FILE.svg or FILE.png
  std::string data;    // FILE.svg.data.csv, beside the chart
  std::string script;  // FILE.svg.gp, beside the chart
};

// The data and script paths beside a chart path; throws std::invalid_argument unless it ends in
// .svg or .png, or when it holds a quote or a control character.
ChartFiles chart_files(const std::string& chart_path);

// The chart and its two companions, for check_outputs(); `flag` names who asked for them.
std::vector<PlannedFile> planned_files(const ChartFiles& files, const std::string& flag);

// The gnuplot `set terminal ...; set output ...` lines for the chart's extension (900x600 by default):
// the output is the chart's absolute path unless the variable numlab_output names another.
std::string gnuplot_output_lines(const ChartFiles& files, int width = 900, int height = 600);

// Writes the data and the script (each whole or not at all), then runs gnuplot (found on PATH) on the
// script, drawing into a temporary beside the chart that is renamed into place only when gnuplot
// exited 0 and the chart is whole (an SVG ends with </svg>, a PNG with its IEND chunk). gnuplot's
// own output is captured, never printed. Throws std::runtime_error naming the chart when gnuplot is
// missing or fails or writes a truncated chart; the temporary is then removed.
void draw_chart(const ChartFiles& files, const std::string& csv, const std::string& script);

}  // namespace numlab::cli
