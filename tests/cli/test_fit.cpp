// `numlab fit` (docs/cli.md): JSON fields, NIST's certified digits through the CLI, warnings,
// failures, charts, the Jansen foot path, and bad input.

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "run_numlab.hpp"

using Catch::Matchers::Contains;
using numlab::test::require_bad_input;
using numlab::test::run_json;
using numlab::test::run_numlab;
using numlab::test::temporary_file;
using numlab::test::temporary_folder;

namespace {

const std::string nist = NUMLAB_NIST_DIR;

}  // namespace

TEST_CASE("numlab fit: JSON fields, and Wampler5's certified digits for every method", "[cli][fit]") {
  // Minimum digits over the coefficients, as measured (GSL 2.7): the scaled normal equations beat GSL.
  const std::map<std::string, std::pair<double, double>> digits = {
      {"normal", {6.0, 6.5}}, {"normal-scaled", {8.5, 15.0}}, {"gsl", {5.5, 6.5}}, {"eigen-qr", {6.3, 15.0}}};
  for (const auto& [method, range] : digits) {
    for (const char* extension : {".dat", ".csv"}) {
      INFO(method << extension);
      const auto json =
          run_json("fit", "--data " + nist + "/Wampler5" + extension + " --degree 5 --method " + method, 0);
      for (const char* field : {"method", "degree", "coefficients", "residual_sd", "r_squared", "condition_estimate",
                                "warning", "status", "time_s"}) {
        CHECK(json.contains(field));
      }
      CHECK(json["method"] == method);
      CHECK(json["status"] == "converged");
      CHECK(json["coefficients"].size() == 6);
      CHECK(json["warning"].is_null());
      // NIST certifies residual sd 23601450.2379268 and R^2 0.224668921574940E-02.
      CHECK(json["residual_sd"].get<double>() == Approx(23601450.2379268).epsilon(1e-9));
      CHECK(json["r_squared"].get<double>() == Approx(0.224668921574940E-02).epsilon(1e-6));
      if (std::string(extension) == ".dat") {
        // The .dat file carries the certified values; the LRE of each coefficient comes with them.
        const double min_lre = json["certified"]["min_lre"].get<double>();
        CHECK(min_lre >= range.first);
        CHECK(min_lre <= range.second);
      } else {
        CHECK_FALSE(json.contains("certified"));
        for (const auto& b : json["coefficients"]) CHECK(std::abs(b.get<double>() - 1.0) < std::pow(10.0, -range.first));
      }
    }
  }
}

TEST_CASE("numlab fit: the normal equations by Gauss-Seidel converge on a scaled, small system", "[cli][fit]") {
  const auto json = run_json("fit", "--data " + nist + "/Norris.dat --degree 1 --method normal-scaled --linear gauss-seidel", 0);
  CHECK(json["linear"] == "gauss-seidel");
  CHECK(json["iterations"].get<int>() > 1);
  CHECK(json["certified"]["min_lre"].get<double>() >= 12.0);
}

TEST_CASE("numlab fit: an untrustworthy fit says so in JSON and in plain text", "[cli][fit][warning]") {
  // Degree 7 on 30 points of [1, 2]: kappa of V^T V (equilibrated) is about 1/eps.
  std::string csv = "x,y\n";
  for (int i = 0; i < 30; ++i) {
    const double x = 1.0 + i / 29.0;
    csv += std::to_string(x) + "," + std::to_string(std::sin(3.0 * x)) + "\n";
  }
  const std::string file = temporary_file("ill.csv", csv);
  const auto json = run_json("fit", "--data " + file + " --degree 7 --method normal", 0);
  REQUIRE(json["warning"].is_string());
  CHECK_THAT(json["warning"].get<std::string>(), Contains("no correct digits"));
  CHECK(json["condition_estimate"].get<double>() * std::numeric_limits<double>::epsilon() >= 0.5);
  const auto text = run_numlab("fit --data " + file + " --degree 7 --method normal");
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("WARNING:") && Contains("NOT to be trusted"));
  // The same fit on the scaled variable carries no warning.
  const auto scaled = run_json("fit", "--data " + file + " --degree 7 --method normal-scaled", 0);
  CHECK(scaled["warning"].is_null());
}

TEST_CASE("numlab fit: a singular normal matrix gives exit 1 and no coefficients", "[cli][fit][failure]") {
  const auto json = run_json("fit", "--data " + nist + "/Wampler4.dat --degree 12 --method normal", 1);
  CHECK(json["status"] == "singular");
  CHECK(json["coefficients"].is_null());
  CHECK_THAT(json["warning"].get<std::string>(), Contains("negligible pivot"));
  const auto text = run_numlab("fit --data " + nist + "/Wampler4.dat --degree 12 --method normal");
  CHECK(text.exit_code == 1);
  CHECK_THAT(text.out, Contains("no coefficients"));
}

TEST_CASE("numlab fit: the Jansen foot path's arcs, normal equations against GSL", "[cli][fit][jansen]") {
  for (const char* arc : {"upper", "lower"}) {
    INFO(arc);
    const auto normal = run_json("fit", std::string("--foot-path ") + arc + " --degree 5 --method normal", 0);
    const auto gsl = run_json("fit", std::string("--foot-path ") + arc + " --degree 5 --method gsl", 0);
    // Expected agreement from the conditioning: 16 - log10(kappa) digits, less one for safety.
    const double kappa = normal["condition_estimate"].get<double>();
    const double tolerance = 10.0 * kappa * std::numeric_limits<double>::epsilon();
    REQUIRE(normal["coefficients"].size() == 6);
    for (std::size_t k = 0; k < 6; ++k) {
      const double b = normal["coefficients"][k].get<double>();
      const double reference = gsl["coefficients"][k].get<double>();
      CHECK(std::abs(b - reference) <= tolerance * std::abs(reference));
    }
    // The arcs meet at the extreme x of the path, so both span the same x range (n differs).
    CHECK(normal["n"].get<int>() > 100);
  }
}

TEST_CASE("numlab fit --chart draws the data with the curve, and writes its CSV and script", "[cli][fit][chart]") {
  const std::string folder = temporary_folder();
  const auto run = run_numlab("fit --data " + nist + "/Pontius.dat --degree 2 --method normal-scaled --chart " + folder +
                              "/pontius.svg");
  CHECK(run.exit_code == 0);
  for (const char* file : {"/pontius.svg", "/pontius.svg.data.csv", "/pontius.svg.gp"}) CHECK(std::filesystem::exists(folder + file));
  std::ifstream svg(folder + "/pontius.svg");
  const std::string contents((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  CHECK_THAT(contents, Contains("<svg") && Contains("degree-2 fit"));
  std::filesystem::remove_all(folder);
}

TEST_CASE("numlab fit: bad input gets one error line and exit 2", "[cli][fit][input]") {
  const std::string not_numeric = temporary_file("bad-value.csv", "x,y\n1,2\n2,abc\n3,4\n");
  require_bad_input("fit --data " + not_numeric + " --degree 1", "line 3, column y: 'abc' is not a number");
  const std::string no_y = temporary_file("no-y.csv", "x,z\n1,2\n2,3\n");
  require_bad_input("fit --data " + no_y + " --degree 1", "no 'y' column");
  const std::string short_row = temporary_file("short.csv", "x,y\n1,2\n2\n");
  require_bad_input("fit --data " + short_row + " --degree 1", "line 3: 1 values");
  const std::string nan_value = temporary_file("nan.csv", "x,y\n1,2\n2,nan\n3,1\n");
  require_bad_input("fit --data " + nan_value + " --degree 1", "'nan' is not");
  require_bad_input("fit --data " + nist + "/Norris.dat --degree 36", "degree 36 needs at least 37 points");
  require_bad_input("fit --data " + nist + "/Norris.dat --degree -1", "degree must be >= 0");
  require_bad_input("fit --data /no/such/file.csv --degree 1", "cannot open the file");
  require_bad_input("fit --data " + nist + "/Norris.dat --degree 1 --method svd", "unknown fit method 'svd'");
  require_bad_input("fit --data " + nist + "/Norris.dat --degree 1 --linear jacobi", "unknown linear solver 'jacobi'");
  require_bad_input("fit --data " + nist + "/Norris.dat --degree 1 --chart out.pdf", "must end in .svg or .png");
  require_bad_input("fit --degree 1", "give --data FILE or --foot-path ARC");
  require_bad_input("fit --foot-path middle --degree 1", "expected upper or lower");
  require_bad_input("fit --data " + nist + "/Longley.dat --degree 1", "no 'x' column");
}
