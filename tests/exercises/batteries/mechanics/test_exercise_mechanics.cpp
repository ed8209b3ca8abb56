// The batteries of polyfit, jansen-jacobian, jansen-newton and mustang-newton, in-process: every
// check passes on the C++ reference solutions, and a mutant of each (one bug) fails the check
// that names it, with a message that points at the bug.

#include <catch2/catch.hpp>
#include <iostream>

#include "exercises/checker.hpp"
#include "exercises/function_session.hpp"
#include "jansen_jacobian.cpp"
#include "jansen_newton.cpp"
#include "mustang_newton.cpp"
#include "polyfit.cpp"

using namespace numlab::exercises;
using Solver = FunctionSession::Solver;

namespace {

// Answers with `solve`, echoing the id as the protocol loop would.
Solver echoing(std::function<nlohmann::json(const nlohmann::json&)> solve) {
  return [solve](const nlohmann::json& request) {
    nlohmann::json reply = solve(request);
    reply["id"] = request["id"];
    return reply;
  };
}

std::vector<CheckResult> run(const std::string& name, Solver solver) {
  FunctionSession session(name, echoing(std::move(solver)));
  return run_checks(find_exercise(name), session);
}

void require_all_pass(const std::string& name, Solver solver) {
  const auto results = run(name, std::move(solver));
  REQUIRE(!results.empty());
  for (const CheckResult& result : results) {
    INFO(result.name << ": " << result.message << " / " << result.hint);
    CHECK(result.status == CheckStatus::pass);
  }
}

// The check whose name contains `check` fails (not error), and its message contains `words`.
void require_caught(const std::string& name, Solver solver, const std::string& check, const std::string& words) {
  const auto results = run(name, std::move(solver));
  bool found = false;
  for (const CheckResult& result : results) {
    if (result.name.find(check) == std::string::npos) continue;
    found = true;
    INFO(result.name << ": " << to_string(result.status) << ": " << result.message << " / " << result.hint);
    CHECK(result.status == CheckStatus::fail);
    CHECK(result.message.find(words) != std::string::npos);
    std::cout << name << " mutant: " << result.message << "\n  hint: " << result.hint << "\n";
  }
  CHECK(found);
}

}  // namespace

TEST_CASE("polyfit: the C++ reference passes every check") { require_all_pass("polyfit", polyfit_reference::solve); }

TEST_CASE("jansen-jacobian: the C++ reference passes every check") {
  require_all_pass("jansen-jacobian", jansen_jacobian_reference::solve);
}

TEST_CASE("jansen-newton: the C++ reference passes every check") {
  require_all_pass("jansen-newton", jansen_newton_reference::solve);
}

TEST_CASE("mustang-newton: the C++ reference passes every check") {
  require_all_pass("mustang-newton", mustang_newton_reference::solve);
}

TEST_CASE("polyfit: powers reversed are caught by the small fits") {
  require_caught("polyfit", [](const nlohmann::json& request) {
    nlohmann::json reply = polyfit_reference::solve(request);
    if (reply.contains("coefficients")) {
      auto b = reply["coefficients"].get<std::vector<double>>();
      reply["coefficients"] = std::vector<double>(b.rbegin(), b.rend());
    }
    return reply;
  }, "Small fits", "powers reversed");
}

TEST_CASE("polyfit: only the status words pass the undetermined fits; others are named as not status words") {
  for (const std::string word : {"ok", "", "passed", "Singular", "converged"}) {
    INFO("status \"" << word << "\"");
    require_caught("polyfit", [word](const nlohmann::json& request) {
      nlohmann::json reply = polyfit_reference::solve(request);
      if (reply.contains("status")) reply = {{"status", word}};
      return reply;
    }, "fewer distinct x", "expected a status saying so: \"singular\"");
    if (word == "converged") continue;
    require_caught("polyfit", [word](const nlohmann::json& request) {
      nlohmann::json reply = polyfit_reference::solve(request);
      if (reply.contains("status")) reply = {{"status", word}};
      return reply;
    }, "fewer distinct x", "is not a status word of polyfit (the words: \"converged\", \"singular\")");
  }
}

TEST_CASE("polyfit: a status other than \"converged\" on a determined fit fails, even with coefficients") {
  require_caught("polyfit", [](const nlohmann::json& request) {
    nlohmann::json reply = polyfit_reference::solve(request);
    reply["status"] = reply.contains("coefficients") ? "ok" : "singular";
    return reply;
  }, "Small fits", "the reply gives status \"ok\"; \"ok\" is not a status word of polyfit");
}

TEST_CASE("jansen-jacobian: a mistyped length (69.1 for l6 = 61.9) is named by its entry") {
  require_caught("jansen-jacobian", [](const nlohmann::json& request) {
    nlohmann::json reply = jansen_jacobian_reference::solve(request);
    for (int row : {4, 5}) reply["J"][row][5] = reply["J"][row][5].get<double>() * 69.1 / 61.9;
    return reply;
  }, "J is the derivative", "J[4][5]");
}

TEST_CASE("jansen-newton: x <- x - dx is caught at iteration 1 with the sign hint") {
  const Solver mutant = [](const nlohmann::json& request) {
    const double crank = request["crank_angle"].get<double>();
    const auto start = numlab::exercise::vector(request["theta0"]);
    auto wrong_way = [crank](const jansen_reference::Vector8& x, jansen_reference::Vector8& f, jansen_reference::Matrix8& J) {
      jansen_reference::closure(crank, x, f, J);
      J = -J;  // dx solves J dx = -f, then x <- x - dx
    };
    return newton_reference::newton<8>(wrong_way, jansen_reference::Vector8(start.data()),
                                       request["tolerance"].get<double>(), request["max_iterations"].get<int>(), "theta");
  };
  require_caught("jansen-newton", mutant, "The trace follows", "iteration 1:");
}

TEST_CASE("mustang-newton: seed 003's flipped loop-3 Jacobian row is caught") {
  const Solver mutant = [](const nlohmann::json& request) {
    const double theta = request["crank_angle"].get<double>();
    const auto guess = numlab::exercise::vector(request["guess"]);
    const auto lengths = mustang_newton_reference::lengths_of(request);
    auto flipped = [theta, lengths](const mustang_newton_reference::Vector8& x, mustang_newton_reference::Vector8& f,
                                    mustang_newton_reference::Matrix8& J) {
      mustang_newton_reference::closure(theta, x, lengths, f, J);
      J(5, 4) = -J(5, 4);
      J(5, 5) = -J(5, 5);
    };
    return newton_reference::newton<8>(flipped, mustang_newton_reference::Vector8(guess.data()),
                                       request["tolerance"].get<double>(), request["max_iterations"].get<int>(), "angles");
  };
  require_caught("mustang-newton", mutant, "The trace follows", "iteration 1:");
}

TEST_CASE("jansen-jacobian: a column from the wrong angle is named with the angle it used") {
  require_caught("jansen-jacobian", [](const nlohmann::json& request) {
    nlohmann::json wrong = request;
    wrong["theta"][2] = request["theta"][3];  // column 2 evaluated at theta4
    nlohmann::json reply = jansen_jacobian_reference::solve(request);
    const nlohmann::json other = jansen_jacobian_reference::solve(wrong);
    for (int row = 0; row < 8; ++row) reply["J"][row][2] = other["J"][row][2];
    return reply;
  }, "J is the derivative", "J[2][2]");
}

TEST_CASE("jansen-newton: one more step after the residual passed is caught by the count and diagnosed") {
  const Solver extra_step = [](const nlohmann::json& request) {
    nlohmann::json reply = jansen_newton_reference::solve(request);
    if (reply["status"] != "converged") return reply;
    const double crank = request["crank_angle"].get<double>();
    const auto angles = reply["theta"].get<std::vector<double>>();
    jansen_reference::Vector8 x(angles.data()), f;
    jansen_reference::Matrix8 J;
    jansen_reference::closure(crank, x, f, J);
    const jansen_reference::Vector8 dx = J.partialPivLu().solve(-f);
    x += dx;
    jansen_reference::closure(crank, x, f, J);
    reply["trace"].push_back({{"residual_inf", f.lpNorm<Eigen::Infinity>()}, {"step_inf", dx.lpNorm<Eigen::Infinity>()}});
    reply["iterations"] = reply["iterations"].get<int>() + 1;
    reply["theta"] = std::vector<double>(x.data(), x.data() + 8);
    return reply;
  };
  require_caught("jansen-newton", extra_step, "The trace follows", "numlab's Newton from the same start takes");
  const auto diagnosis = overall_diagnosis(run("jansen-newton", extra_step));
  REQUIRE(diagnosis);
  CHECK(diagnosis->cause == "one_iteration_too_many");
}
