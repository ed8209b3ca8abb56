#include "bench/bench_linear.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bench/progress_line.hpp"
#include "bench/bench_basins.hpp"
#include "bench/bench_fit.hpp"
#include "bench/bench_jansen.hpp"
#include "bench/bench_linkage_scaling.hpp"
#include "bench/bench_mustang.hpp"
#include "bench/bench_robustness.hpp"
#include "output/chart.hpp"
#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/measures.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "bench/bench_all.hpp"
#include "output/table.hpp"
#include "bench/timing.hpp"

namespace numlab::cli {

namespace {

const std::vector<std::string> solvers = {"gepp", "gsl-lu", "eigen-lu", "gauss-seidel", "gauss-seidel-plain"};

// Times one solver object's solve(A, b); returns the row, or nothing when it did not converge.
template <typename Solver, typename MatrixType, typename VectorType>
void time_solver(std::vector<BenchRow>& rows, const std::string& name, Solver& solver, const MatrixType& A,
                 const VectorType& b, const TimingPlan& plan) {
  show_progress(fmt::format("bench linear: {} at n = {}", name, A.rows()));
  const auto result = solver.solve(A, b);
  if (result.status != Status::converged) return;  // Gauss-Seidel is timed only where it converges
  const double seconds = median_time([&] { solver.solve(A, b); }, plan);
  const Eigen::VectorXd x = result.x;
  rows.push_back({name, static_cast<int>(A.rows()), seconds, linalg::forward_error(x, Eigen::VectorXd::Ones(x.size()))});
}

// Every solver on one diagonally dominant system of size n (N = n for fixed-size code).
template <int N>
void bench_size(std::vector<BenchRow>& rows, int n, const TimingPlan& plan) {
  const linalg::GeneratedSystem system = linalg::generate_system("diag-dominant", n);
  const linalg::Matrix<N> A = system.A;
  const linalg::Vector<N> b = system.b;

  linalg::GaussElimination<N> gepp;
  time_solver(rows, "gepp", gepp, A, b, plan);
  linalg::GslLu gsl_lu(n);
  time_solver(rows, "gsl-lu", gsl_lu, system.A, system.b, plan);
  linalg::EigenLu<N> eigen_lu;
  time_solver(rows, "eigen-lu", eigen_lu, A, b, plan);

  linalg::GaussSeidelOptions options;
  options.max_iterations = 100000;
  linalg::GaussSeidel<N> normal_equations(options);
  time_solver(rows, "gauss-seidel", normal_equations, A, b, plan);
  options.system = linalg::GaussSeidelOptions::System::plain;
  linalg::GaussSeidel<N> plain(options);
  time_solver(rows, "gauss-seidel-plain", plain, A, b, plan);
}

double time_of(const std::vector<BenchRow>& rows, const std::string& solver, int n) {
  for (const BenchRow& row : rows) {
    if (row.solver == solver && row.n == n) return row.time_s;
  }
  return std::nan("");
}

std::string chart_script(const ChartFiles& files, const std::vector<BenchRow>& rows, const std::vector<int>& sizes) {
  // Anchor the n^3 guide at the largest GEPP point.
  double anchor = 1e-9;
  for (const BenchRow& row : rows) {
    if (row.solver == "gepp") anchor = row.time_s / std::pow(row.n, 3.0);
  }
  std::string script = "# Median time per solve against n (numlab bench linear). Redraw: gnuplot " + files.script + "\n";
  script += gnuplot_output_lines(files);
  script += "set datafile separator ','\nset logscale xy\nset grid\nset key top left box opaque\n";
  script += "set title 'Linear solvers: median time per solve (diagonally dominant A)'\n";
  script += "set xlabel 'n'\nset ylabel 'time per solve (s)'\nset format y '10^{%T}'\n";
  script += fmt::format("guide(n) = {:.6g} * n**3\n", anchor);
  const auto [smallest, largest] = std::minmax_element(sizes.begin(), sizes.end());
  script += fmt::format("set xrange [{}:{}]\nset xtics (", *smallest / 1.5, *largest * 1.5);
  for (std::size_t i = 0; i < sizes.size(); ++i) script += fmt::format("{}{}", i ? ", " : "", sizes[i]);
  script += ")\n";
  script += "plot ";
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    script += fmt::format("'{}' using 1:{} with linespoints lw 2 pt {} title '{}', ", files.data, i + 2, i + 5, solvers[i]);
  }
  script += fmt::format("[{}:{}] guide(x) with lines dt 2 lc rgb 'gray40' title 'n^3 guide'\n", *smallest, *largest);
  return script;
}

std::string chart_data(const std::vector<BenchRow>& rows, const std::vector<int>& sizes) {
  std::string csv = "n";
  for (const std::string& solver : solvers) csv += "," + solver;
  csv += '\n';
  for (int n : sizes) {
    csv += std::to_string(n);
    for (const std::string& solver : solvers) {
      const double seconds = time_of(rows, solver, n);
      csv += std::isnan(seconds) ? ",NaN" : fmt::format(",{:.6g}", seconds);
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace

Table linear_bench_table(const std::vector<BenchRow>& rows, const std::vector<int>& sizes) {
  std::vector<std::string> header = {"n"};
  for (const std::string& solver : solvers) header.push_back(solver);
  Table table(header);
  for (int n : sizes) {
    std::vector<std::string> cells = {std::to_string(n)};
    const double reference = time_of(rows, "gsl-lu", n);
    for (const std::string& solver : solvers) {
      const double seconds = time_of(rows, solver, n);
      cells.push_back(std::isnan(seconds) ? "-" : fmt::format("{:.3g} s ({:.2f}x)", seconds, seconds / reference));
    }
    table.add_row(cells);
  }
  return table;
}

void draw_linear_chart(const ChartFiles& files, const std::vector<BenchRow>& rows, const std::vector<int>& sizes) {
  draw_chart(files, chart_data(rows, sizes), chart_script(files, rows, sizes));
}

std::vector<BenchRow> bench_linear(const std::vector<int>& sizes, bool quick) {
  const TimingPlan plan = quick ? TimingPlan{3, 50, 0.002} : TimingPlan{5, 100000, 0.3};
  std::vector<BenchRow> rows;
  for (int n : sizes) {
    if (n == 2) {
      bench_size<2>(rows, n, plan);
    } else if (n == 8) {
      bench_size<8>(rows, n, plan);
    } else {
      bench_size<Eigen::Dynamic>(rows, n, plan);
    }
  }
  show_progress("");
  return rows;
}

int run_linear_bench(const BenchOptions& common, const std::string& chart, const std::vector<int>& sizes, bool quick) {
  const ChartFiles files = chart_files(chart.empty() ? common.out_dir + "/bench-linear.svg" : chart);
  check_outputs(planned_files(files, chart.empty() ? "bench linear's chart" : "--chart"), {});
  const std::vector<BenchRow> rows = bench_linear(sizes, quick);
  draw_linear_chart(files, rows, sizes);

  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "linear"}, {"chart", files.chart}, {"rows", nlohmann::ordered_json::array()}};
    for (const BenchRow& row : rows) {
      out["rows"].push_back({{"solver", row.solver},
                             {"n", row.n},
                             {"time_s", row.time_s},
                             {"ratio_to_gsl_lu", row.time_s / time_of(rows, "gsl-lu", row.n)},
                             {"error", row.error}});
    }
    std::cout << out.dump(2) << '\n';
  } else if (common.format == Format::csv) {
    std::cout << "solver,n,time_s,ratio_to_gsl_lu,error\n";
    for (const BenchRow& row : rows) {
      std::cout << fmt::format("{},{},{:.6g},{:.4g},{:.3g}\n", row.solver, row.n, row.time_s,
                               row.time_s / time_of(rows, "gsl-lu", row.n), row.error);
    }
  } else {
    std::cout << "Median time per solve (diagonally dominant A, b = A * ones), and the ratio to GSL LU\n"
              << "(below 1 is faster than GSL). Gauss-Seidel runs to tolerance 1e-9; '-' = not measured.\n\n";
    linear_bench_table(rows, sizes).print(std::cout);
    std::cout << "\nChart: " << files.chart << " (data " << files.data << ", script " << files.script << ")\n";
  }
  return exit_success;
}

int run_jansen_bench(const BenchOptions& common, bool quick) {
  const double tolerance = common.tolerance.value_or(1e-10);
  auto rows = bench_jansen(mechanisms::JansenModel::eight_equations, tolerance, quick);
  const auto file_rows = bench_jansen_file(tolerance, quick);
  rows.insert(rows.end(), file_rows.begin(), file_rows.end());
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "jansen"}, {"rows", nlohmann::ordered_json::array()}};
    for (const auto& row : rows) {
      out["rows"].push_back({{"solver", row.solver},
                             {"tolerance", row.tolerance},
                             {"time_s", row.time_s},
                             {"error", number_or_null(row.error)},
                             {"iterations", row.iterations}});
    }
    std::cout << out.dump(2) << '\n';
  } else {
    print_jansen_bench(std::cout, rows);
  }
  return exit_success;
}

}  // namespace numlab::cli
