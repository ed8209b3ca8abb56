// numlab's own test cases, f, J and GSL's hybridsj, served to a script (minpack_crosscheck.py)
// over stdin and stdout, so that the script compares MINPACK with GSL on numlab's exact f and J
// without writing them again. One request per line, one JSON line in reply:
//
//   cases                   {"cases": [{"label", "problem", "n", "factor", "start": [...]}, ...]}
//   eval I x_1 ... x_n      {"f": [...], "J": [[row 1], ...]}  (case I's system at x)
//   gsl I LIMIT             {"status", "x", "residual_inf", "iterations", "f_evaluations", "j_evaluations"}
//                           GSL's hybridsj from case I's start, at most LIMIT iterations, stopping
//                           when sum |f_i| < 1e-10 (gsl_multiroot_test_residual)
//
// A bad request gets {"error": "..."} and the evaluator goes on.

#include <Eigen/Core>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/minpack_cases.hpp"

namespace {

using numlab::nonlinear::minpack_cases;

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

const numlab::nonlinear::MinpackCase& case_at(std::istringstream& words) {
  std::size_t index = 0;
  if (!(words >> index) || index >= minpack_cases().size()) throw std::invalid_argument("no such case");
  return minpack_cases()[index];
}

nlohmann::json list_cases() {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& test_case : minpack_cases()) {
    const auto instance = numlab::nonlinear::make_minpack_instance(test_case);
    cases.push_back({{"label", numlab::nonlinear::case_label(test_case)}, {"problem", test_case.problem},
                     {"n", test_case.n}, {"factor", test_case.factor}, {"start", as_vector(instance.start)}});
  }
  return {{"cases", cases}};
}

nlohmann::json evaluate(std::istringstream& words) {
  const auto instance = numlab::nonlinear::make_minpack_instance(case_at(words));
  const int n = instance.problem.system->dimension();
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) {
    // strtod, not >>: a solver may try a point with nan or inf in it, and f there is an answer too.
    std::string word;
    char* end = nullptr;
    if (!(words >> word) || (x(i) = std::strtod(word.c_str(), &end), *end != '\0')) {
      throw std::invalid_argument("eval needs " + std::to_string(n) + " numbers");
    }
  }
  Eigen::VectorXd f(n);
  Eigen::MatrixXd J(n, n);
  instance.problem.system->residual_and_jacobian(x, f, J);
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < n; ++i) rows.push_back(as_vector(J.row(i).transpose()));
  return {{"f", as_vector(f)}, {"J", rows}};
}

nlohmann::json run_gsl(std::istringstream& words) {
  const auto instance = numlab::nonlinear::make_minpack_instance(case_at(words));
  numlab::nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-10;
  if (!(words >> options.max_iterations)) throw std::invalid_argument("gsl needs an iteration limit");
  const auto result = numlab::nonlinear::gsl_multiroot_solve(*instance.problem.system, instance.start, "hybridsj", options);
  return {{"status", std::string(numlab::to_string(result.status))}, {"x", as_vector(result.x)},
          {"residual_inf", result.residual_norm}, {"iterations", result.iterations},
          {"f_evaluations", result.function_evaluations}, {"j_evaluations", result.jacobian_evaluations}};
}

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream words(line);
    std::string request;
    words >> request;
    nlohmann::json reply;
    try {
      if (request == "cases") {
        reply = list_cases();
      } else if (request == "eval") {
        reply = evaluate(words);
      } else if (request == "gsl") {
        reply = run_gsl(words);
      } else {
        reply = {{"error", "unknown request '" + request + "'"}};
      }
    } catch (const std::exception& error) {
      reply = {{"error", error.what()}};
    }
    std::cout << reply.dump() << std::endl;
  }
  return 0;
}
