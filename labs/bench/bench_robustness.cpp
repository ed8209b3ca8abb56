#include "bench/bench_robustness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench/progress_line.hpp"
#include "bench/performance_profiles.hpp"

namespace numlab::cli {

namespace {

std::string start_text(const nonlinear::MinpackCase& test_case) {
  return fmt::format("{}x0", static_cast<long>(test_case.factor));
}

// costs[case][solver] of the profiled solvers: `cost` of a solved run, +infinity otherwise.
template <typename Cost>
CostTable cost_table(const RobustnessResults& results, Cost cost) {
  CostTable table;
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    std::vector<double> row;
    for (const std::string& solver : profiled_solvers(results)) {
      const RobustnessRun& run = results.run(static_cast<int>(c), solver);
      row.push_back(run.solved ? cost(run) : not_solved);
    }
    table.push_back(row);
  }
  return table;
}

ProfileCurves ratio_profile(const RobustnessResults& results, const CostTable& costs, const std::string& what) {
  const CostTable ratios = performance_ratios(costs);
  ProfileCurves curves{fmt::format("Performance profile on {} ({} cases)", what, results.cases.size()),
                       "tau: within tau times the least " + what + " of any solver", solved_definition(), true,
                       profiled_solvers(results), ratio_breakpoints(ratios), {}};
  for (std::size_t s = 0; s < curves.solvers.size(); ++s) {
    std::vector<double> values;
    for (double tau : curves.x) values.push_back(performance_profile(ratios, static_cast<int>(s), tau));
    curves.values.push_back(values);
  }
  return curves;
}

std::string markdown(const Table& table) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string text = "|";
    for (const std::string& cell : cells) text += " " + cell + " |";
    return text + "\n";
  };
  std::string text = line(table.header());
  text += line(std::vector<std::string>(table.header().size(), "---"));
  for (const auto& row : table.rows()) text += line(row);
  return text;
}

std::string runs_csv(const RobustnessResults& results) {
  std::string csv = "problem,n,start,solver,outcome,status,residual_inf,iterations,f_evaluations,j_evaluations,evaluations,time_s\n";
  for (const RobustnessRun& run : results.runs) {
    const nonlinear::MinpackCase& test_case = results.cases.at(run.case_index);
    if (!run.applies) {
      csv += fmt::format("{},{},{},{},n/a,,,,,,,\n", test_case.problem, test_case.n, start_text(test_case), run.solver);
      continue;
    }
    csv += fmt::format("{},{},{},{},{},{},{:.3e},{},{},{},{:g},{:.4g}\n", test_case.problem, test_case.n,
                       start_text(test_case), run.solver, run.solved ? "solved" : "failed", to_string(run.status),
                       run.residual_norm, run.iterations, run.function_evaluations, run.jacobian_evaluations,
                       run.evaluations, run.time_s);
  }
  return csv;
}

}  // namespace

std::string solved_definition() {
  return fmt::format("solved: ||f(x)||_inf <= {:g} at the returned x (not the solver's own status); "
                     "budget 100 (n+1) iterations for every solver (MINPACK's default)",
                     solved_tolerance);
}

std::vector<std::string> profiled_solvers(const RobustnessResults& results) {
  std::vector<std::string> solvers;
  std::copy_if(results.solvers.begin(), results.solvers.end(), std::back_inserter(solvers), applies_everywhere);
  return solvers;
}

int solved_count(const RobustnessResults& results, const std::string& solver) {
  return static_cast<int>(std::count_if(results.runs.begin(), results.runs.end(),
                                        [&](const RobustnessRun& run) { return run.solver == solver && run.solved; }));
}

int applicable_count(const RobustnessResults& results, const std::string& solver) {
  return static_cast<int>(std::count_if(results.runs.begin(), results.runs.end(),
                                        [&](const RobustnessRun& run) { return run.solver == solver && run.applies; }));
}

Table success_counts_table(const RobustnessResults& results) {
  Table table({"solver", "solved", "applies to", "cases", "median evaluations (solved)"});
  for (const std::string& solver : results.solvers) {
    std::vector<double> evaluations;
    for (const RobustnessRun& run : results.runs) {
      if (run.solver == solver && run.solved) evaluations.push_back(run.evaluations);
    }
    std::string median = "-";
    if (!evaluations.empty()) {
      std::nth_element(evaluations.begin(), evaluations.begin() + evaluations.size() / 2, evaluations.end());
      median = fmt::format("{:g}", evaluations[evaluations.size() / 2]);
    }
    table.add_row({solver, std::to_string(solved_count(results, solver)), std::to_string(applicable_count(results, solver)),
                   std::to_string(results.cases.size()), median});
  }
  return table;
}

Table success_table(const RobustnessResults& results) {
  std::vector<std::string> header = {"problem", "n", "start"};
  for (const std::string& solver : results.solvers) header.push_back(solver);
  Table table(header);
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    const nonlinear::MinpackCase& test_case = results.cases[c];
    std::vector<std::string> row = {test_case.problem, std::to_string(test_case.n), start_text(test_case)};
    for (const std::string& solver : results.solvers) row.push_back(outcome_text(results.run(static_cast<int>(c), solver)));
    table.add_row(row);
  }
  return table;
}

ProfileCurves time_profile(const RobustnessResults& results) {
  return ratio_profile(results, cost_table(results, [](const RobustnessRun& run) { return run.time_s; }), "time");
}

ProfileCurves evaluation_profile(const RobustnessResults& results) {
  return ratio_profile(results, cost_table(results, [](const RobustnessRun& run) { return run.evaluations; }),
                       "function evaluations");
}

ProfileCurves data_profile_curves(const RobustnessResults& results) {
  const CostTable evaluations = cost_table(results, [](const RobustnessRun& run) { return run.evaluations; });
  std::vector<int> sizes;
  for (const auto& test_case : results.cases) sizes.push_back(test_case.n);
  ProfileCurves curves{fmt::format("Data profile ({} cases): solved within kappa (n+1) function evaluations", results.cases.size()),
                       "kappa: evaluations / (n+1), a Jacobian counted as n evaluations", solved_definition(), false,
                       profiled_solvers(results), data_breakpoints(evaluations, sizes), {}};
  for (std::size_t s = 0; s < curves.solvers.size(); ++s) {
    std::vector<double> values;
    for (double kappa : curves.x) values.push_back(data_profile(evaluations, sizes, static_cast<int>(s), kappa));
    curves.values.push_back(values);
  }
  return curves;
}

RobustnessFiles robustness_files(const std::string& folder) {
  return {folder + "/robustness-success.csv",
          folder + "/robustness-success.txt",
          folder + "/robustness-success.md",
          chart_files(folder + "/robustness-profile-time.svg"),
          chart_files(folder + "/robustness-profile-evaluations.svg"),
          chart_files(folder + "/robustness-data-profile.svg")};
}

std::vector<PlannedFile> planned_files(const RobustnessFiles& files) {
  std::vector<PlannedFile> planned = {{files.csv, "the success table (CSV)"},
                                      {files.text, "the success table (text)"},
                                      {files.markdown, "the success table (markdown)"}};
  for (const auto& [chart, name] : {std::pair{&files.time_chart, "the time profile"},
                                    std::pair{&files.evaluation_chart, "the evaluation profile"},
                                    std::pair{&files.data_chart, "the data profile"}}) {
    for (const PlannedFile& file : planned_files(*chart, name)) planned.push_back(file);
  }
  return planned;
}

void write_robustness_files(const RobustnessFiles& files, const RobustnessResults& results) {
  ensure_directory(std::filesystem::path(files.csv).parent_path().string());
  write_file_atomically(files.csv, runs_csv(results));
  std::ostringstream text;
  text << "MINPACK test cases, every solver. " << solved_definition() << ".\n\n";
  success_counts_table(results).print(text);
  text << "\nOutcome per case ('solved', or the solver's status and the final ||f||_inf; n/a: does not apply)\n\n";
  success_table(results).print(text);
  write_file_atomically(files.text, text.str());
  write_file_atomically(files.markdown, "Solved counts (" + solved_definition() + ")\n\n" +
                                            markdown(success_counts_table(results)) + "\nOutcome per case\n\n" +
                                            markdown(success_table(results)));
  draw_profile_chart(files.time_chart, time_profile(results));
  draw_profile_chart(files.evaluation_chart, evaluation_profile(results));
  draw_profile_chart(files.data_chart, data_profile_curves(results));
}

int run_bench_robustness(const BenchOptions& common, bool quick) {
  const RobustnessFiles files = robustness_files(common.out_dir);
  check_outputs(planned_files(files), {});
  const RobustnessResults results = run_robustness(nonlinear::minpack_cases(), quick ? 1 : 5, show_progress);
  show_progress("");
  write_robustness_files(files, results);
  const std::vector<std::string> written = {files.csv, files.text, files.markdown, files.time_chart.chart,
                                            files.evaluation_chart.chart, files.data_chart.chart};
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "robustness"}, {"solved_definition", solved_definition()},
                                  {"cases", results.cases.size()}, {"repeats", results.repeats},
                                  {"files", written}, {"solvers", nlohmann::ordered_json::array()},
                                  {"runs", nlohmann::ordered_json::array()}};
    for (const std::string& solver : results.solvers) {
      out["solvers"].push_back({{"solver", solver}, {"solved", solved_count(results, solver)},
                                {"applies", applicable_count(results, solver)}});
    }
    for (const RobustnessRun& run : results.runs) {
      const nonlinear::MinpackCase& test_case = results.cases.at(run.case_index);
      nlohmann::ordered_json row = {{"problem", test_case.problem}, {"n", test_case.n}, {"factor", test_case.factor},
                                    {"solver", run.solver}, {"applies", run.applies}};
      if (run.applies) {
        row.update({{"solved", run.solved}, {"status", std::string(to_string(run.status))},
                    {"residual_inf", number_or_null(run.residual_norm)}, {"iterations", run.iterations},
                    {"f_evaluations", run.function_evaluations}, {"j_evaluations", run.jacobian_evaluations},
                    {"evaluations", run.evaluations}, {"time_s", run.time_s}});
      } else {
        row["not_applicable"] = run.not_applicable;
      }
      out["runs"].push_back(row);
    }
    std::cout << out.dump(2) << '\n';
    return exit_success;
  }
  std::cout << fmt::format("{} MINPACK test cases, {} solvers; times are medians of {} run{}.\n{}.\n\n",
                           results.cases.size(), results.solvers.size(), results.repeats,
                           results.repeats == 1 ? "" : "s", solved_definition());
  success_counts_table(results).print(std::cout);
  std::cout << "\nFiles (each chart with its CSV and gnuplot script beside it):\n";
  for (const std::string& path : written) std::cout << "  " << path << '\n';
  return exit_success;
}

}  // namespace numlab::cli
