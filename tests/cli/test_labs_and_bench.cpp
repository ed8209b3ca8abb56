// `numlab labs`, `numlab lab NAME --step` (non-interactive), `numlab bench linear`, and the main job.

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>
#include <nlohmann/json.hpp>
#include <set>

#include "run_numlab.hpp"

using numlab::test::run_json;
using numlab::test::run_numlab;
using numlab::test::temporary_folder;
using Catch::Matchers::Contains;

namespace {

std::string file_text(const std::string& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// A lab's report.html: a whole HTML page with every step the lab printed, every table it saved,
// and every figure (SVG or PNG) in the lab's folder, named in a caption and embedded.
void check_report(const std::string& lab_folder, const std::string& printed) {
  const std::string path = lab_folder + "/report.html";
  INFO(path);
  REQUIRE(std::filesystem::exists(path));
  CHECK_THAT(printed, Contains("Report: " + path));
  const std::string html = file_text(path);
  CHECK(html.starts_with("<!DOCTYPE html>"));
  CHECK_THAT(html, Contains("</html>"));
  // No external references: the page reads offline.
  CHECK(html.find("src=\"http") == std::string::npos);
  CHECK(html.find("href=\"http") == std::string::npos);
  for (int step = 1; printed.find("Step " + std::to_string(step) + ":") != std::string::npos; ++step) {
    CHECK_THAT(html, Contains("<h2 id=\"step" + std::to_string(step) + "\">Step " + std::to_string(step) + ":"));
  }
  for (const auto& entry : std::filesystem::directory_iterator(lab_folder)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = entry.path().extension().string();
    INFO(name);
    if (extension == ".svg" || extension == ".png") {
      CHECK_THAT(html, Contains("<figcaption><code>" + name + "</code>"));
    } else if (extension == ".csv" && name.starts_with("step")) {
      CHECK_THAT(html, Contains("Table saved as <code>" + name + "</code>"));
    }
  }
  // Every embedded figure is inline: as many <figure>s as pictures in the folder.
  std::size_t figures = 0, pictures = 0;
  for (std::size_t at = html.find("<figure>"); at != std::string::npos; at = html.find("<figure>", at + 1)) ++figures;
  for (const auto& entry : std::filesystem::directory_iterator(lab_folder)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".svg" || extension == ".png") ++pictures;
  }
  CHECK(figures == pictures);
}

}  // namespace

TEST_CASE("numlab labs lists the labs", "[cli][labs]") {
  const auto run = run_numlab("labs");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("gauss") && Contains("seidel") && Contains("inverse2x2") && Contains("newton") &&
                          Contains("jansen-sequential") && Contains("beest") && Contains("mustang") &&
                          Contains("fit"));
}

TEST_CASE("Each lab runs its steps with --step without blocking, and saves its comparison table", "[cli][labs]") {
  // Each lab's table that compares its methods (with GSL's where GSL has the method; jansen-sequential
  // compares models and solvers), and that table's header.
  const std::map<std::string, std::pair<std::string, std::string>> comparisons = {
      {"gauss", {"step5-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"seidel", {"step4-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"inverse2x2", {"step4-comparison.csv", "method,status,x_1,x_n,relative residual,forward error,time (median)"}},
      {"newton", {"step3-rosenbrock.csv", "method,status,iterations,||f||_inf,distance,f evals,J evals,time"}},
      {"jansen-sequential",
       {"step3-costs.csv", "model / solver,time per cycle,iterations,worst error"}},
      {"mustang", {"step7-solvers.csv", "solver,time per sweep (s),x full,iterations,error"}},
      {"fit",
       {"step2-nist-lre.csv",
        "data,D,normal,normal (Gauss-Seidel),normal-scaled,gsl,eigen-qr,kappa normal,kappa scaled,kappa gsl"}}};
  for (const auto& [lab, comparison] : comparisons) {
    const std::string folder = temporary_folder();
    const auto run = run_numlab("lab " + lab + " --step --out " + folder);
    INFO(lab << "\n" << run.err);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("Step 1:") && Contains("Step 3:"));
    // Every table is also saved as CSV, the comparison among them.
    const std::string saved = folder + "/lab-" + lab + "/" + comparison.first;
    std::ifstream csv(saved);
    REQUIRE(csv.good());
    std::string header;
    std::getline(csv, header);
    CHECK(header == comparison.second);
    CHECK_THAT(run.out, Contains("(table saved as " + saved + ")"));
    check_report(folder + "/lab-" + lab, run.out);
    std::filesystem::remove_all(folder);
  }
  const auto gauss = run_numlab("lab gauss");
  CHECK_THAT(gauss.out, Contains("Wilkinson") && Contains("5.76e+17"));
  const auto seidel = run_numlab("lab seidel");
  CHECK_THAT(seidel.out, Contains("gauss-seidel-plain: diverged") && Contains("gauss-seidel: converged"));
  const auto inverse = run_numlab("lab inverse2x2");
  CHECK_THAT(inverse.out, Contains("singular"));
  const auto newton = run_numlab("lab newton");
  CHECK_THAT(newton.out, Contains("J(9,10) = -61.6554; AutoDiff -60.0113") && Contains("Step 6:") &&
                             Contains("{theta5, theta8 from eqs 7-8}"));
  const auto unknown = run_numlab("lab nosuchlab");
  CHECK(unknown.exit_code == 2);
}

TEST_CASE("numlab with no arguments runs the main job: the Jansen lab, with its scene", "[cli][jansen]") {
  const auto run = run_numlab("");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("main job: the Jansen leg lab") && Contains("Step 4:") && Contains("gsl-newton") &&
                          Contains("Figure: out/lab-jansen/leg.svg"));
  check_report("out/lab-jansen", run.out);
  CHECK(std::filesystem::file_size("out/lab-jansen/leg.svg") > 1000);
  CHECK(std::filesystem::file_size("out/lab-jansen/leg-animated.svg") > 10000);
}

TEST_CASE("The jansen-sequential lab draws Figure 4 and the beest lab draws four legs from one cycle", "[cli][jansen]") {
  const std::string folder = temporary_folder();
  const auto sequential = run_numlab("lab jansen-sequential --out " + folder);
  CHECK(sequential.exit_code == 0);
  CHECK(std::filesystem::file_size(folder + "/lab-jansen-sequential/figure4.svg") > 1000);
  CHECK(std::filesystem::exists(folder + "/lab-jansen-sequential/figure4.svg.gp"));
  check_report(folder + "/lab-jansen-sequential", sequential.out);
  const auto beest = run_numlab("lab beest --out " + folder);
  CHECK(beest.exit_code == 0);
  CHECK_THAT(beest.out, Contains("Solved: 360 poses"));
  check_report(folder + "/lab-beest", beest.out);
  std::ifstream drawing(folder + "/lab-beest/beest-animated.svg");
  const std::string svg((std::istreambuf_iterator<char>(drawing)), std::istreambuf_iterator<char>());
  CHECK(svg.find("<animate") != std::string::npos);
  // four legs of eleven bars each
  std::size_t lines = 0;
  for (std::size_t at = svg.find("<line"); at != std::string::npos; at = svg.find("<line", at + 1)) ++lines;
  CHECK(lines == 4 * 11 + 1);  // plus the body
  std::filesystem::remove_all(folder);
}

TEST_CASE("numlab bench linear: JSON rows, a chart, and its data and script beside it", "[cli][bench]") {
  const std::string folder = temporary_folder();
  const auto run = run_numlab("bench linear --quick --sizes 2,8,32 --format json --chart " + folder + "/linear.svg");
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto out = nlohmann::json::parse(run.out);
  std::set<std::string> solvers;
  for (const auto& row : out["rows"]) {
    solvers.insert(row["solver"].get<std::string>());
    CHECK(row["time_s"].get<double>() > 0.0);
    CHECK(row["error"].get<double>() < 1e-6);
    CHECK((row["n"] == 2 || row["n"] == 8 || row["n"] == 32));
  }
  CHECK(solvers == std::set<std::string>{"gepp", "gsl-lu", "eigen-lu", "gauss-seidel", "gauss-seidel-plain"});
  CHECK(out["rows"].size() == 15);
  CHECK(std::filesystem::file_size(folder + "/linear.svg") > 1000);
  CHECK(std::filesystem::exists(folder + "/linear.svg.data.csv"));
  CHECK(std::filesystem::exists(folder + "/linear.svg.gp"));
  std::filesystem::remove_all(folder);

  const auto bad_chart = run_numlab("bench linear --quick --sizes 2 --chart chart.pdf");
  CHECK(bad_chart.exit_code == 2);
  CHECK_THAT(bad_chart.err, Contains(".svg or .png"));
}

TEST_CASE("numlab bench jansen measures the textbook paths beside the fast ones",
          "[cli][bench]") {
  const auto out = run_json("bench jansen", "--quick", 0);
  const auto row_of = [&](const std::string& solver) {
    for (const auto& row : out["rows"]) {
      if (row["solver"] == solver) return row;
    }
    FAIL("no row " << solver);
    return out["rows"][0];
  };
  for (const std::string solver : {"full-std-sin", "sequential-textbook"}) {
    INFO(solver);
    const auto row = row_of(solver);
    CHECK(row["error"].get<double>() < 1e-8);
    CHECK(row["time_s"].get<double>() > 0.0);
  }
  // The same method, so the same iterations: only the sines (full) or the stepper (sequential) differ.
  CHECK(row_of("full-std-sin")["iterations"] == row_of("full")["iterations"]);
  CHECK(row_of("sequential-textbook")["iterations"] == row_of("sequential")["iterations"]);
  const auto text = run_numlab("bench jansen --quick");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("full, std::sin"));
  CHECK_THAT(text.out, Contains("sequential, textbook"));
}

TEST_CASE("numlab bench quick-return: whitworth.toml against a hand-written Newton and the closed form, the 2x verdict",
          "[cli][bench]") {
  const auto out = run_json("bench quick-return", "--quick", 0);
  REQUIRE(out["rows"].size() == 5);
  std::map<std::string, nlohmann::json> rows;
  for (const auto& row : out["rows"]) rows[row["solver"].get<std::string>()] = row;
  // Every row solves the 360 poses within its residual test (1e-10 x the 450 mm rod): within 1e-6 mm
  // of the closed form (measured 5.8e-10 full, 8.3e-8 sequential, 3.8e-8 hand-written).
  for (const std::string solver : {"whitworth.toml, full", "whitworth.toml, sequential", "whitworth.toml, analytic",
                                    "hand-written Newton"}) {
    INFO(solver);
    REQUIRE(rows.count(solver) == 1);
    REQUIRE(rows[solver]["error"].is_number());
    CHECK(rows[solver]["error"].get<double>() < 1e-6);
    if (solver != "whitworth.toml, analytic") CHECK(rows[solver]["iterations"].get<int>() >= 300);  // closed form: none
    CHECK(rows[solver]["time_s"].get<double>() > 0.0);
  }
  CHECK(rows["hand-written Newton"]["ratio_to_hand_written"].get<double>() == 1.0);
  const double ratio = rows["whitworth.toml, analytic"]["ratio_to_hand_written"].get<double>();
  CHECK(out["file_within_2x"].get<bool>() == (ratio <= 2.0));
  const double full = rows["whitworth.toml, full"]["ratio_to_hand_written"].get<double>();
  CHECK(out["full_newton_within_2x"].get<bool>() == (full <= 2.0));
  const auto text = run_numlab("bench quick-return --quick");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("whitworth.toml (derived, analytic: its 3 blocks in closed form) vs hand-written Newton:"));
}

TEST_CASE("numlab bench with no argument: work-precision rows for every Jansen solver, and every chart",
          "[cli][bench]") {
  const std::string folder = temporary_folder();
  const auto run = run_numlab("bench --quick --format json --out " + folder + " --chart " + folder + "/wp.svg");
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto out = nlohmann::json::parse(run.out);
  CHECK(out["benchmark"] == "all");
  // Jansen rows: each solver at every tolerance of the sweep (quick: 1e-2, 1e-6, 1e-10, 1e-13), the closed form once.
  std::map<std::string, std::set<double>> tolerances;
  std::set<std::string> benches;
  for (const auto& row : out["rows"]) {
    for (const char* field : {"solver", "tolerance", "time_s", "error"}) CHECK(row.contains(field));
    CHECK(row["time_s"].get<double>() > 0.0);
    benches.insert(row["bench"].get<std::string>());
    if (row["bench"] == "jansen") tolerances[row["solver"]].insert(row["tolerance"].get<double>());
    if (row["bench"] == "linear" || row["bench"] == "seidel" || row["bench"] == "fit") CHECK(row.contains("n"));
  }
  CHECK(benches == std::set<std::string>{"jansen", "mustang", "linear", "seidel", "fit"});
  CHECK(tolerances.at("analytic").size() == 1);
  std::set<double> mustang_tolerances;
  for (const auto& row : out["rows"]) {
    if (row["bench"] == "mustang" && row["solver"] == "sequential") mustang_tolerances.insert(row["tolerance"].get<double>());
  }
  CHECK(mustang_tolerances == std::set<double>{1e-2, 1e-6, 1e-10, 1e-13});
  for (const char* solver :
       {"full", "full-std-sin", "full-gauss-seidel", "full-gsl-lu", "full-eigen-lu", "sequential", "gsl-newton"}) {
    INFO(solver);
    CHECK(tolerances.at(solver) == std::set<double>{1e-2, 1e-6, 1e-10, 1e-13});
  }
  // Precision follows the tolerance: full Newton's worst joint error at 1e-13 is below its error at 1e-2.
  double loose = 0.0, tight = 0.0;
  for (const auto& row : out["rows"]) {
    if (row["bench"] != "jansen" || row["solver"] != "full") continue;
    if (row["tolerance"].get<double>() == 1e-2) loose = row["error"].get<double>();
    if (row["tolerance"].get<double>() == 1e-13) tight = row["error"].get<double>();
  }
  CHECK(tight < 1e-10);
  CHECK(loose > 1e3 * tight);
  // Every chart, with its CSV and gnuplot script beside it; --chart names the work-precision diagram.
  REQUIRE(out["charts"].size() == 5);
  CHECK(out["charts"][0]["chart"] == folder + "/wp.svg");
  for (const auto& chart : out["charts"]) {
    for (const char* file : {"chart", "data", "script"}) CHECK(std::filesystem::exists(chart[file].get<std::string>()));
  }
  std::filesystem::remove_all(folder);
}

TEST_CASE("numlab bench fit: every method at degrees 1 .. 12 on Wampler4, digits bounded by the conditioning",
          "[cli][bench][fitting]") {
  const std::string folder = temporary_folder();
  const auto out = run_json("bench fit", "--quick --out " + folder, 0);
  CHECK(out["benchmark"] == "fit");
  REQUIRE(out["rows"].size() == 48);  // 4 methods x 12 degrees
  CHECK(std::filesystem::exists(folder + "/bench-fit.svg"));
  CHECK(std::filesystem::exists(folder + "/bench-fit.svg.data.csv"));
  CHECK(std::filesystem::exists(folder + "/bench-fit.svg.gp"));
  for (const auto& row : out["rows"]) {
    const std::string method = row["solver"];
    const int degree = row["degree"];
    INFO(method << " degree " << degree);
    CHECK(row["time_s"].get<double>() > 0.0);
    // A backward-stable solve keeps about 16 - log10(kappa) digits of the matrix it solves (V for
    // the QR methods, V^T V for the normal equations); two digits of slack for the data's own error.
    if (row["status"] == "converged" && !row["condition"].is_null()) {
      const double kappa = row["condition"];
      if (degree <= 5) CHECK(row["digits"].get<double>() >= 16.0 - std::log10(kappa) - 2.0);
    }
  }
  std::filesystem::remove_all(folder);
}
