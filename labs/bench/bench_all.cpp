#include "bench/bench_all.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "bench/progress_line.hpp"
#include "bench/bench_fit.hpp"
#include "bench/bench_jansen.hpp"
#include "bench/bench_linear.hpp"
#include "bench/bench_mustang.hpp"
#include "methods/data_dir.hpp"
#include "output/chart.hpp"
#include "output/fit_charts.hpp"
#include "numlab/fitting/degree_sweep.hpp"
#include "methods/linear_methods.hpp"
#include "numlab/fitting/data_set.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "output/table.hpp"
#include "bench/timing.hpp"

namespace numlab::cli {

namespace {

// --- Jansen and Mustang: work-precision diagrams ---

// One solver at one Newton tolerance: median time per cycle or sweep, and the worst joint error.
struct WorkPrecisionPoint {
  std::string solver;
  double tolerance;
  double time_s;
  double error;
  int iterations;
};

std::vector<double> tolerance_sweep(bool quick) {
  if (quick) return {1e-2, 1e-6, 1e-10, 1e-13};
  std::vector<double> tolerances;
  for (int exponent = 2; exponent <= 13; ++exponent) tolerances.push_back(std::pow(10.0, -exponent));
  return tolerances;
}

// Runs `bench_at(tolerance)` over the sweep. The closed form does not depend on the tolerance:
// it is kept once. Each solver's rows end up together, loosest tolerance first.
template <typename BenchAt>
std::vector<WorkPrecisionPoint> work_precision_points(const std::string& what, bool quick, BenchAt bench_at) {
  std::vector<WorkPrecisionPoint> points;
  for (double tolerance : tolerance_sweep(quick)) {
    show_progress(fmt::format("bench: {} at tolerance {:g}", what, tolerance));
    for (const auto& row : bench_at(tolerance)) {
      const bool repeat = row.solver == "analytic" &&
                          std::any_of(points.begin(), points.end(), [](const auto& p) { return p.solver == "analytic"; });
      if (!repeat) points.push_back({row.solver, row.tolerance, row.time_s, row.error, row.iterations});
    }
  }
  std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.solver < b.solver; });
  return points;
}

void draw_work_precision(const ChartFiles& files, const std::string& title, const std::vector<WorkPrecisionPoint>& points) {
  constexpr double floor = 1e-17;  // an exact match still needs a place on a log axis
  std::string csv = "solver,tolerance,time_s,error\n";
  std::vector<std::string> solvers;
  for (const auto& point : points) {
    csv += fmt::format("{},{:g},{:.6g},{:.6g}\n", point.solver, point.tolerance, point.time_s, std::max(point.error, floor));
    if (std::find(solvers.begin(), solvers.end(), point.solver) == solvers.end()) solvers.push_back(point.solver);
  }
  // Hand-written solvers solid, GSL's dashed; every line its own colour and marker.
  static const std::vector<std::string> colours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                                                   "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#000080", "#808000",
                                                   "#800000", "#008080", "#ff1493", "#556b2f"};
  std::string plots;
  for (std::size_t s = 0; s < solvers.size(); ++s) {
    const bool closed_form = solvers[s] == "analytic";
    const std::string style =
        closed_form ? "with points pt 7 ps 2.5 lc rgb 'black'"
                    : fmt::format("with linespoints lw 2 pt {} ps 1.2 dt {} lc rgb '{}'", 4 + s % 10,
                                  solvers[s].starts_with("gsl-") ? 2 : 1, colours[s % colours.size()]);
    plots += fmt::format("{}'{}' using (strcol(1) eq '{}' ? $4 : 1/0):3 skip 1 {} title '{}'", s ? ", " : "",
                         files.data, solvers[s], style, closed_form ? "closed form" : solvers[s]);
  }
  std::string script = "# Work-precision diagram (numlab bench): median time per run against the worst joint error\n"
                       "# vs the closed form, one line per solver over Newton tolerances 1e-2..1e-13.\n";
  script += gnuplot_output_lines(files, 1100, 650);
  script += "set datafile separator ','\nset logscale xy\nset grid\nset key outside right box opaque\n"
            "set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04\n"
            "set xlabel 'worst joint error vs the closed form (length units)'\nset ylabel 'median time per run (s)'\n"
            "set format x '10^{%T}'\nset format y '10^{%T}'\n";
  script += fmt::format("set title '{} (lower left is better)'\nplot {}\n", title, plots);
  draw_chart(files, csv, script);
}

// Rows: solvers; columns: tolerances; cells: time (error). The closed form fills its first column only.
Table work_precision_table(const std::vector<WorkPrecisionPoint>& points, const std::vector<double>& tolerances) {
  std::vector<std::string> header = {"solver"};
  for (double tolerance : tolerances) header.push_back(fmt::format("{:g}", tolerance));
  Table table(header);
  for (std::size_t first = 0; first < points.size();) {
    std::vector<std::string> cells = {points[first].solver};
    std::size_t next = first;
    for (double tolerance : tolerances) {
      const bool here = next < points.size() && points[next].solver == points[first].solver &&
                        points[next].tolerance == tolerance;
      cells.push_back(here ? fmt::format("{:.3g} ms ({:.0e})", points[next].time_s * 1e3, points[next].error) : "");
      if (here) ++next;
    }
    if (next == first) ++next;  // the closed form: one point, at the first tolerance
    first = next;
    table.add_row(cells);
  }
  return table;
}

// --- Gauss-Seidel: sweeps against kappa ---

struct SeidelRow {
  double kappa;
  int sweeps;
  double time_s;
  double error;
};

std::vector<SeidelRow> seidel_rows(bool quick) {
  std::vector<SeidelRow> rows;
  constexpr int n = 8;
  for (double kappa : {2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0}) {
    show_progress(fmt::format("bench: Gauss-Seidel at kappa {:g}", kappa));
    const Eigen::MatrixXd A = linalg::matrix_with_condition(n, kappa, 7);
    const Eigen::VectorXd exact = Eigen::VectorXd::Ones(n);
    const Eigen::VectorXd b = A * exact;
    LinearSettings settings;
    settings.max_iterations = 10000000;
    const DynamicResult result = run_linear_method("gauss-seidel", A, b, settings);
    const TimingPlan plan = quick ? TimingPlan{3, 5, 0.0} : TimingPlan{5, 200, 0.1};
    const double seconds = median_time([&] { run_linear_method("gauss-seidel", A, b, settings); }, plan);
    rows.push_back({kappa, result.iterations, seconds, linalg::forward_error(result.x, exact)});
  }
  return rows;
}

void draw_seidel_chart(const ChartFiles& files, const std::vector<SeidelRow>& rows) {
  std::string csv = "kappa,sweeps,time_s,forward_error\n";
  for (const auto& row : rows) csv += fmt::format("{:g},{},{:.6g},{:.3g}\n", row.kappa, row.sweeps, row.time_s, row.error);
  const double anchor = rows.back().sweeps / (rows.back().kappa * rows.back().kappa);
  std::string script = "# Gauss-Seidel on the normal equations: sweeps to converge against kappa(A) (numlab bench).\n";
  script += gnuplot_output_lines(files);
  script += fmt::format(
      "set datafile separator ','\nset logscale xy\nset grid\nset key top left box opaque\n"
      "set xlabel 'kappa_2(A)'\nset ylabel 'sweeps to tolerance 1e-9'\n"
      "set title 'Gauss-Seidel on A^T A x = A^T b (n = 8): sweeps grow like kappa^2'\n"
      "plot '{}' using 1:2 skip 1 with linespoints lw 2 pt 7 title 'sweeps', "
      "{:.6g} * x**2 with lines dt 2 lc rgb 'gray40' title 'kappa^2 guide'\n",
      files.data, anchor);
  draw_chart(files, csv, script);
}

// --- bench all: the steps ---

// The five charts, each with its CSV and gnuplot script beside it.
struct AllCharts {
  ChartFiles work_precision, linear, seidel, fit, mustang;
  std::vector<ChartFiles> in_order() const { return {work_precision, mustang, linear, seidel, fit}; }
};

// 1. Every file name is checked before any measuring starts.
AllCharts checked_charts(const BenchOptions& common, const std::string& chart) {
  const AllCharts charts{chart_files(chart.empty() ? common.out_dir + "/work-precision.svg" : chart),
                         chart_files(common.out_dir + "/bench-linear.svg"), chart_files(common.out_dir + "/bench-seidel.svg"),
                         chart_files(common.out_dir + "/bench-fit.svg"),
                         chart_files(common.out_dir + "/work-precision-mustang.svg")};
  std::vector<PlannedFile> outputs = planned_files(charts.work_precision, chart.empty() ? "the work-precision chart" : "--chart");
  for (const auto& [files, name] : {std::pair{&charts.mustang, "the Mustang chart"}, std::pair{&charts.linear, "the linear chart"},
                                    std::pair{&charts.seidel, "the Gauss-Seidel chart"}, std::pair{&charts.fit, "the fit chart"}}) {
    for (const PlannedFile& file : planned_files(*files, name)) outputs.push_back(file);
  }
  check_outputs(outputs, {});
  return charts;
}

// Everything bench all measures.
struct AllMeasurements {
  // The rows at tolerance 1e-10 are kept whole for the ratio tables.
  std::vector<JansenBenchRow> jansen_at_1e10;
  std::vector<MustangBenchRow> mustang_at_1e10;
  std::vector<WorkPrecisionPoint> jansen, mustang;
  std::vector<int> sizes;
  std::vector<BenchRow> linear;
  std::vector<SeidelRow> seidel;
  std::vector<FitBenchRow> fits;
  std::vector<fitting::DegreeSweepRow> sweep;
};

// 2. Measure: warm-up, repeated runs, medians (timing.hpp).
AllMeasurements measure_all(const fitting::DataSet& wampler, bool quick) {
  AllMeasurements m;
  m.jansen = work_precision_points("Jansen cycle", quick, [&](double tolerance) {
    auto rows = bench_jansen(mechanisms::JansenModel::eight_equations, tolerance, quick);
    if (tolerance == 1e-10) m.jansen_at_1e10 = rows;
    return rows;
  });
  m.mustang = work_precision_points("Mustang sweep", quick, [&](double tolerance) {
    auto rows = bench_mustang(tolerance, quick);
    if (tolerance == 1e-10) m.mustang_at_1e10 = rows;
    return rows;
  });
  m.sizes = quick ? std::vector<int>{2, 8, 64} : std::vector<int>{2, 8, 64, 256, 512, 1024};
  m.linear = bench_linear(m.sizes, quick);
  m.seidel = seidel_rows(quick);
  show_progress("bench: fitting degree sweep on Wampler4");
  m.fits = bench_fit("Wampler4", wampler, 12, quick);
  for (const FitBenchRow& row : m.fits) m.sweep.push_back(row.sweep);
  show_progress("");
  return m;
}

// 3. Draw.
void draw_all(const AllCharts& charts, const AllMeasurements& m) {
  draw_work_precision(charts.work_precision, "Jansen leg, 360-pose cycle", m.jansen);
  draw_work_precision(charts.mustang, "Mustang roof linkage, 195-pose sweep over its assembly range", m.mustang);
  draw_linear_chart(charts.linear, m.linear, m.sizes);
  draw_seidel_chart(charts.seidel, m.seidel);
  draw_degree_sweep_chart(charts.fit, "NIST Wampler4: digits and residual against degree", m.sweep);
}

// 4. Report, JSON: the charts and one row per measurement.
void print_all_json(const AllCharts& charts, const AllMeasurements& m, const fitting::DataSet& wampler) {
  nlohmann::ordered_json out = {{"benchmark", "all"}, {"charts", nlohmann::ordered_json::array()},
                                {"rows", nlohmann::ordered_json::array()}};
  for (const auto& files : charts.in_order()) out["charts"].push_back({{"chart", files.chart}, {"data", files.data}, {"script", files.script}});
  for (const auto& [bench, points] : {std::pair{"jansen", &m.jansen}, std::pair{"mustang", &m.mustang}}) {
    for (const auto& point : *points) {
      out["rows"].push_back({{"bench", bench}, {"solver", point.solver}, {"tolerance", point.tolerance},
                             {"time_s", point.time_s}, {"error", number_or_null(point.error)},
                             {"iterations", point.iterations}});
    }
  }
  for (const auto& row : m.linear) {
    out["rows"].push_back({{"bench", "linear"}, {"solver", row.solver}, {"tolerance", nullptr}, {"time_s", row.time_s},
                           {"error", number_or_null(row.error)}, {"n", row.n}});
  }
  for (const auto& row : m.seidel) {
    out["rows"].push_back({{"bench", "seidel"}, {"solver", "gauss-seidel"}, {"tolerance", 1e-9}, {"time_s", row.time_s},
                           {"error", number_or_null(row.error)}, {"n", 8}, {"kappa", row.kappa}, {"sweeps", row.sweeps}});
  }
  for (const auto& row : m.fits) {
    out["rows"].push_back({{"bench", "fit"}, {"solver", row.sweep.method}, {"tolerance", nullptr},
                           {"time_s", row.time_s},
                           // error: the relative coefficient error behind the digits (10^-digits)
                           {"error", std::isfinite(row.sweep.residual_sd) ? number_or_null(std::pow(10.0, -row.sweep.digits))
                                                                          : nlohmann::ordered_json()},
                           {"n", wampler.x.size()}, {"data", row.data}, {"degree", row.sweep.degree},
                           {"digits", row.sweep.digits}, {"status", std::string(to_string(row.sweep.status))}});
  }
  std::cout << out.dump(2) << '\n';
}

// 4. Report, text: one table per benchmark, then where the charts are.
void print_all_text(const AllCharts& charts, const AllMeasurements& m, bool quick) {
  print_jansen_bench(std::cout, m.jansen_at_1e10);
  std::cout << "\nJansen work-precision: median time per cycle (worst joint error) at each Newton tolerance.\n";
  work_precision_table(m.jansen, tolerance_sweep(quick)).print(std::cout);
  std::cout << '\n';
  print_mustang_bench(std::cout, m.mustang_at_1e10);
  std::cout << "\nMustang work-precision: median time per sweep (worst joint error) at each Newton tolerance.\n";
  work_precision_table(m.mustang, tolerance_sweep(quick)).print(std::cout);
  std::cout << "\nLinear solvers: median time per solve (diagonally dominant A), and the ratio to GSL LU\n";
  linear_bench_table(m.linear, m.sizes).print(std::cout);
  std::cout << "\nGauss-Seidel on the normal equations (n = 8): sweeps against kappa(A)\n";
  Table sweeps({"kappa", "sweeps", "sweeps / kappa^2", "time", "forward error"});
  for (const auto& row : m.seidel) {
    sweeps.add_row({fmt::format("{:g}", row.kappa), std::to_string(row.sweeps),
                    fmt::format("{:.2f}", row.sweeps / (row.kappa * row.kappa)), fmt::format("{:.3g} s", row.time_s),
                    scientific(row.error)});
  }
  sweeps.print(std::cout);
  std::cout << "\nFitting, NIST Wampler4: correct digits (weighted, vs a long-double reference) per degree\n";
  print_fit_digits(std::cout, m.fits);
  std::cout << "\nCharts (each with its CSV and gnuplot script beside it):\n";
  for (const auto& files : charts.in_order()) std::cout << "  " << files.chart << '\n';
}

}  // namespace

int run_bench_all(const BenchOptions& common, const std::string& chart, bool quick) {
  const AllCharts charts = checked_charts(common, chart);
  const fitting::DataSet wampler = fitting::read_nist_data(nist_data_dir() + "/Wampler4.dat");
  const AllMeasurements measured = measure_all(wampler, quick);
  draw_all(charts, measured);
  if (common.format == Format::json) {
    print_all_json(charts, measured, wampler);
  } else {
    print_all_text(charts, measured, quick);
  }
  return exit_success;
}

}  // namespace numlab::cli
