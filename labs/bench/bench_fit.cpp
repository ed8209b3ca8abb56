#include "bench/bench_fit.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/timing.hpp"
#include "methods/data_dir.hpp"
#include "output/chart.hpp"
#include "output/fit_charts.hpp"
#include "output/table.hpp"

namespace numlab::cli {

std::vector<FitBenchRow> bench_fit(const std::string& data_name, const fitting::DataSet& data, int max_degree,
                                   bool quick) {
  const std::vector<fitting::DegreeSweepRow> sweep = fitting::fit_degree_sweep(data.x, data.y, max_degree);
  std::vector<FitBenchRow> rows;
  const TimingPlan plan = quick ? TimingPlan{3, 5, 0.0} : TimingPlan{5, 200, 0.02};
  for (const fitting::DegreeSweepRow& row : sweep) {
    fitting::FitOptions options;
    options.method = fitting::fit_method_from_string(row.method);
    options.degree = row.degree;
    const double seconds = median_time([&] { fitting::fit_polynomial(data.x, data.y, options); }, plan);
    rows.push_back({row, data_name, seconds});
  }
  return rows;
}

void print_fit_digits(std::ostream& out, const std::vector<FitBenchRow>& rows) {
  Table digits({"degree", "normal", "normal-scaled", "gsl", "eigen-qr"});
  for (std::size_t first = 0; first + 3 < rows.size(); first += 4) {
    std::vector<std::string> cells = {std::to_string(rows[first].sweep.degree)};
    for (std::size_t m = 0; m < 4; ++m) {
      const fitting::DegreeSweepRow& row = rows[first + m].sweep;
      cells.push_back(std::isfinite(row.residual_sd) ? fmt::format("{:.1f}", row.digits) : std::string(to_string(row.status)));
    }
    digits.add_row(cells);
  }
  digits.print(out);
}

int run_bench_fit(const BenchOptions& common, const std::string& chart, bool quick) {
  const ChartFiles files = chart_files(chart.empty() ? common.out_dir + "/bench-fit.svg" : chart);
  check_outputs(planned_files(files, chart.empty() ? "bench fit's chart" : "--chart"), {});
  const fitting::DataSet wampler = fitting::read_nist_data(nist_data_dir() + "/Wampler4.dat");
  const std::vector<FitBenchRow> rows = bench_fit("Wampler4", wampler, 12, quick);
  std::vector<fitting::DegreeSweepRow> sweep;
  for (const FitBenchRow& row : rows) sweep.push_back(row.sweep);
  draw_degree_sweep_chart(files, "NIST Wampler4: digits and residual against degree", sweep);

  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "fit"}, {"chart", files.chart}, {"rows", nlohmann::ordered_json::array()}};
    for (const FitBenchRow& row : rows) {
      out["rows"].push_back({{"solver", row.sweep.method}, {"data", row.data}, {"degree", row.sweep.degree},
                             {"time_s", row.time_s}, {"digits", row.sweep.digits},
                             {"condition", number_or_null(row.sweep.condition)},
                             {"status", std::string(to_string(row.sweep.status))}});
    }
    std::cout << out.dump(2) << '\n';
    return exit_success;
  }
  std::cout << "Fitting, NIST Wampler4: correct digits (weighted, vs a long-double reference) per degree\n";
  print_fit_digits(std::cout, rows);
  std::cout << "\nChart: " << files.chart << " (data " << files.data << ", script " << files.script << ")\n";
  return exit_success;
}

}  // namespace numlab::cli
