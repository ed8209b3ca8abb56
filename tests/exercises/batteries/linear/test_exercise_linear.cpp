// The linear exercises' batteries in-process: the C++ reference solutions pass every check, and
// solutions with one known mistake fail the check that names it, with a message (and hint) that
// points at the mistake.

#include <catch2/catch.hpp>
#include <string>

#include "exercises/checker.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/function_session.hpp"
#include "gauss_seidel_solution.hpp"
#include "gepp_solution.hpp"
#include "inverse2x2_solution.hpp"

namespace {

using numlab::exercises::CheckResult;
using numlab::exercises::CheckStatus;
using numlab::exercises::Exercise;
using numlab::exercises::FunctionSession;

// A solver that echoes the request's id, as the protocol loop does.
FunctionSession::Solver serving(std::function<nlohmann::json(const nlohmann::json&)> solve) {
  return [solve](const nlohmann::json& request) {
    nlohmann::json reply = solve(request);
    reply["id"] = request["id"];
    return reply;
  };
}

std::vector<CheckResult> run(const Exercise& exercise, std::function<nlohmann::json(const nlohmann::json&)> solve) {
  FunctionSession session(exercise.name, serving(std::move(solve)));
  return numlab::exercises::run_checks(exercise, session);
}

void require_all_pass(const Exercise& exercise, std::function<nlohmann::json(const nlohmann::json&)> solve) {
  const auto results = run(exercise, std::move(solve));
  REQUIRE(results.size() >= 5);
  for (const CheckResult& result : results) {
    INFO(result.name << ": " << numlab::exercises::to_string(result.status) << ": " << result.message);
    CHECK(result.status == CheckStatus::pass);
    CHECK(!result.references.empty());  // numlab's and GSL's times per request, beside the student's
  }
}

// The check named like `check` fails (not errors) with `message` (and `hint`) in what it says.
void require_caught(const std::vector<CheckResult>& results, const std::string& check, const std::string& message,
                    const std::string& hint = "") {
  bool found = false;
  for (const CheckResult& result : results) {
    if (result.name.find(check) == std::string::npos) continue;
    found = true;
    INFO(result.name << ": " << numlab::exercises::to_string(result.status) << ": " << result.message << " / hint: "
                     << result.hint);
    CHECK(result.status == CheckStatus::fail);
    CHECK(result.message.find(message) != std::string::npos);
    CHECK(result.hint.find(hint) != std::string::npos);
  }
  INFO("no check is named like " << check);
  CHECK(found);
}

nlohmann::json without_trace(nlohmann::json reply) {
  reply.erase("trace");
  return reply;
}

}  // namespace

TEST_CASE("the C++ reference solutions pass every check of gepp, gauss-seidel and inverse2x2") {
  require_all_pass(numlab::exercises::gepp_exercise(), gepp_solution::solve);
  require_all_pass(numlab::exercises::gauss_seidel_exercise(), gauss_seidel_solution::solve);
  require_all_pass(numlab::exercises::inverse2x2_exercise(), inverse2x2_solution::solve);
}

TEST_CASE("gepp: no pivoting is caught at the first column that needs a swap") {
  const auto results = run(numlab::exercises::gepp_exercise(), [](const nlohmann::json& request) {
    return gepp_solution::solve_with(request, gepp_solution::PivotRule::none);
  });
  require_caught(results, "pivot choices (trace)", "column 0: you pivoted on row 0", "no pivoting");
  require_caught(results, "leading entry is tiny", "you replied \"singular\"", "without pivoting");
}

TEST_CASE("gepp: pivoting on the signed value is caught with its hint") {
  const auto results = run(numlab::exercises::gepp_exercise(), [](const nlohmann::json& request) {
    return gepp_solution::solve_with(request, gepp_solution::PivotRule::largest_signed_value);
  });
  require_caught(results, "pivot choices (trace)", "the largest on or below the diagonal is row", "signed value");
}

TEST_CASE("gepp and gauss-seidel: a check that needs the trace fails (not errors) without one") {
  const auto gepp = run(numlab::exercises::gepp_exercise(),
                        [](const nlohmann::json& request) { return without_trace(gepp_solution::solve(request)); });
  require_caught(gepp, "pivot choices (trace)", "no trace in the reply");
  const auto sweeps = run(numlab::exercises::gauss_seidel_exercise(), [](const nlohmann::json& request) {
    return without_trace(gauss_seidel_solution::solve(request));
  });
  require_caught(sweeps, "sweeps (trace)", "no trace in the reply");
  require_caught(sweeps, "converged claim", "no trace in the reply");
}

TEST_CASE("gauss-seidel: seed 001's stop test without abs is caught at the sweep it stops") {
  const auto results = run(numlab::exercises::gauss_seidel_exercise(), [](const nlohmann::json& request) {
    return gauss_seidel_solution::solve_with(request, gauss_seidel_solution::StopTest::signed_change);
  });
  require_caught(results, "converged claim", "reported as converged with tolerance");
  require_caught(results, "converged claim", "your stop test lets a negative change pass");
}

TEST_CASE("inverse2x2: a determinant with the wrong sign is caught with its hint") {
  const auto results = run(numlab::exercises::inverse2x2_exercise(), [](const nlohmann::json& request) {
    nlohmann::json reply = inverse2x2_solution::solve(request);
    if (reply.contains("inverse")) {
      for (auto& row : reply["inverse"]) {
        for (auto& entry : row) entry = -entry.get<double>();
      }
    }
    return reply;
  });
  require_caught(results, "well-conditioned", "the closed form gives", "wrong sign");
}
