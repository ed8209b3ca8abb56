// Variants (docs/exercises.md, "Variants"): the ID's seed is stable (against an independent
// implementation of FNV-1a and SplitMix64, tests/exercises/variants/variant_numbers.py), and every
// battery, run in-process against the C++ reference solutions, sends the same requests for the same
// ID, other requests in each randomised check for another ID, and passes under variants.

#include <catch2/catch.hpp>
#include <functional>
#include <map>
#include <stdexcept>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"
#include "exercises/function_session.hpp"
#include "exercises/variant.hpp"
#include "gauss_seidel_solution.hpp"
#include "gepp_solution.hpp"
#include "inverse2x2_solution.hpp"
#include "jansen10_jacobian.cpp"
#include "jansen_jacobian.cpp"
#include "jansen_newton.cpp"
#include "mustang_newton.cpp"
#include "polyfit.cpp"

using namespace numlab::exercises;

namespace {

using Solve = std::function<nlohmann::json(const nlohmann::json&)>;

// Each exercise's C++ reference, and how many of its checks draw their inputs from a variant (the
// others are hand-made edge cases: Hilbert, Wilkinson, [[1,2,4],[2,1,2],[4,2,1]], NIST's data...).
struct Reference {
  Solve solve;
  int randomised_checks;
};

const std::map<std::string, Reference>& references() {
  static const std::map<std::string, Reference> all = {
      {"gepp", {gepp_solution::solve, 4}},
      {"gauss-seidel", {gauss_seidel_solution::solve, 6}},
      {"inverse2x2", {inverse2x2_solution::solve, 3}},
      {"polyfit", {polyfit_reference::solve, 1}},
      {"jansen-jacobian", {jansen_jacobian_reference::solve, 2}},
      {"jansen10-jacobian", {jansen10_jacobian_reference::solve, 2}},
      {"jansen-newton", {jansen_newton_reference::solve, 3}},
      {"mustang-newton", {mustang_newton_reference::solve, 4}},
  };
  return all;
}

std::vector<CheckResult> run(const std::string& name, const Variant& variant) {
  const Solve solve = references().at(name).solve;
  FunctionSession session(name, [solve](const nlohmann::json& request) {
    nlohmann::json reply = solve(request);
    reply["id"] = request["id"];
    return reply;
  });
  return run_checks(find_exercise(name), session, variant);
}

// The requests of each check, in order.
std::vector<std::vector<nlohmann::json>> requests_of(const std::vector<CheckResult>& results) {
  std::vector<std::vector<nlohmann::json>> requests;
  for (const CheckResult& result : results) {
    requests.emplace_back();
    for (const Exchange& exchange : result.exchanges) requests.back().push_back(exchange.request);
  }
  return requests;
}

void require_all_pass(const std::vector<CheckResult>& results, const std::string& id) {
  for (const CheckResult& result : results) {
    INFO("variant " << id << ": " << result.name << ": " << to_string(result.status) << ": " << result.message);
    CHECK(result.status == CheckStatus::pass);
  }
}

}  // namespace

TEST_CASE("a Variant without an ID leaves every base seed as it is") {
  const Variant none;
  CHECK_FALSE(none.active());
  for (unsigned base : {0u, 1u, 7u, 4294967295u}) CHECK(none.seed(base) == base);
  CHECK(none.seed_where(5, [](unsigned) { return false; }) == 5u);  // never re-drawn: the checks as they were
}

TEST_CASE("a variant's seeds and numbers are FNV-1a and SplitMix64 of the ID, the same on every build") {
  // From variant_numbers.py, an independent implementation in Python.
  CHECK(Variant("s1234567").seed(7) == 3465026638u);
  CHECK(Variant("Zoë").seed(2) == 2549462336u);
  Variant::Stream stream = Variant("s1234567").stream(1);
  CHECK(stream.uniform(0.0, 90.0) == Approx(50.90099601666175).epsilon(1e-15));
  CHECK(stream.uniform(0.0, 90.0) == Approx(44.08785302040255).epsilon(1e-15));
  // Another base or another ID, another seed.
  CHECK(Variant("s1234567").seed(8) != Variant("s1234567").seed(7));
  CHECK(Variant("s1234568").seed(7) != Variant("s1234567").seed(7));
  // A variant never falls back on the seed without one.
  for (unsigned base = 0; base < 200; ++base) CHECK(Variant("b").seed(base) != base);
}

TEST_CASE("a variant ID is a non-empty string without control characters") {
  CHECK_THROWS_AS(Variant(""), std::invalid_argument);
  CHECK_THROWS_AS(Variant("s12\n34"), std::invalid_argument);
  CHECK_THROWS_AS(Variant("s12\t34"), std::invalid_argument);
  CHECK_THROWS_AS(Variant(std::string("a\0b", 3)), std::invalid_argument);
  CHECK(Variant("Zoë Müller, group 3").id() == std::optional<std::string>("Zoë Müller, group 3"));
  CHECK(variant_id_problem("").find("empty") != std::string::npos);
  CHECK(variant_id_problem("s1234567").empty());
}

TEST_CASE("seed_where re-draws from the ID until the draw is valid, the same way each time") {
  const Variant variant("s1234567");
  const auto odd = [](unsigned seed) { return seed % 2 == 1; };
  const unsigned first = variant.seed_where(3, odd);
  CHECK(first % 2 == 1);
  CHECK(variant.seed_where(3, odd) == first);
  int calls = 0;
  CHECK_THROWS_AS(variant.seed_where(3, [&calls](unsigned) { return ++calls < 0; }), std::logic_error);
  CHECK(calls == 1000);
}

TEST_CASE("every battery: the same ID, the same requests; another ID, other requests in every randomised check") {
  for (const auto& [name, reference] : references()) {
    INFO(name);
    const auto plain = requests_of(run(name, Variant()));
    const auto a = run(name, Variant("s1234567"));
    const auto again = run(name, Variant("s1234567"));
    const auto b = run(name, Variant("s7654321"));
    const auto ra = requests_of(a), rb = requests_of(b);
    CHECK(requests_of(again) == ra);
    REQUIRE(ra.size() == plain.size());
    REQUIRE(rb.size() == plain.size());
    int randomised = 0;
    for (std::size_t k = 0; k < plain.size(); ++k) {
      INFO("check " << k + 1 << ": " << a[k].name);
      if (ra[k] == plain[k]) {
        CHECK(rb[k] == plain[k]);  // a hand-made case, the same for every ID
        continue;
      }
      ++randomised;
      CHECK_FALSE(ra[k].empty());
      CHECK(ra[k] != rb[k]);
      CHECK(rb[k] != plain[k]);
    }
    CHECK(randomised == reference.randomised_checks);
  }
}

TEST_CASE("every battery: the C++ reference passes every check under two variants") {
  for (const auto& [name, reference] : references()) {
    for (const char* id : {"s1234567", "Zoë Müller"}) {
      INFO(name << " under " << id);
      require_all_pass(run(name, Variant(id)), id);
    }
  }
}
