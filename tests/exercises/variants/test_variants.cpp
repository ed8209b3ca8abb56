// Variants (docs/exercises.md, "Variants"): the ID's seed is stable (against an independent
// implementation of FNV-1a and SplitMix64, tests/exercises/variants/variant_numbers.py), and every
// battery, run in-process against the C++ reference solutions, sends the same requests for the same
// ID, other requests in each randomised check for another ID, and passes under variants.

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"
#include "exercises/function_session.hpp"
#include "exercises/variant.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"
#include "numlab/nonlinear/newton.hpp"
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

// Link lengths (issue 29 §4): the Jansen exercises' requests carry a variant's lengths.
namespace {

const char* const jansen_exercises[] = {"jansen-jacobian", "jansen10-jacobian", "jansen-newton"};

// Seed 000's lengths by the protocol's names (docs/exercises.md), typed here from the seed.
const std::map<std::string, double>& seed_lengths() {
  static const std::map<std::string, double> lengths = {
      {"crank", 15.0}, {"l1", 50.0}, {"l2", 41.5}, {"l3", 55.8}, {"l4", 40.1}, {"l5", 39.4}, {"l6", 61.9},
      {"l7", 39.3},    {"l8", 36.7}, {"a", 7.8},   {"b", 38.0},  {"l9", 49.0}, {"l10", 65.7}};
  return lengths;
}

numlab::mechanisms::JansenLengths jansen_lengths_of(const nlohmann::json& given) {
  numlab::mechanisms::JansenLengths L;
  L.crank = given["crank"];
  L.l1 = given["l1"], L.l2 = given["l2"], L.l3 = given["l3"], L.l4 = given["l4"];
  L.l5 = given["l5"], L.l6 = given["l6"], L.l7 = given["l7"], L.l8 = given["l8"];
  L.a = given["a"], L.b = given["b"];
  return L;
}

}  // namespace

TEST_CASE("without a variant no Jansen request carries lengths") {
  for (const char* name : jansen_exercises) {
    for (const auto& check : requests_of(run(name, Variant()))) {
      for (const auto& request : check) CHECK_FALSE(request.contains("lengths"));
    }
  }
}

TEST_CASE("under a variant every Jansen request carries the variant's lengths: each within 3% of seed 000's, "
          "other for another ID, and the leg assembles at every crank angle a request names") {
  std::map<std::string, nlohmann::json> by_id;
  for (const char* id : {"s1234567", "alice", "42"}) {
    for (const char* name : jansen_exercises) {
      INFO(name << " under " << id);
      const auto results = run(name, Variant(id));
      require_all_pass(results, id);
      for (const auto& check : requests_of(results)) {
        for (const auto& request : check) {
          REQUIRE(request.contains("lengths"));
          const nlohmann::json& lengths = request["lengths"];
          CHECK(lengths.size() == (std::string(name) == "jansen10-jacobian" ? 13u : 11u));
          for (const auto& [key, value] : lengths.items()) {
            const double seed = seed_lengths().at(key), drawn = value.get<double>();
            CHECK(std::abs(drawn / seed - 1.0) <= 0.03);
            CHECK(drawn != seed);
          }
          // The same leg in every request, and in every Jansen exercise of one ID.
          nlohmann::json eight = lengths;
          eight.erase("l9");
          eight.erase("l10");
          if (!by_id.contains(id)) by_id[id] = eight;
          CHECK(by_id[id] == eight);
          // numlab's closed form assembles the leg at the request's crank angle, independently of
          // the battery's re-draw; and numlab's Newton converges from a Newton request's start.
          const numlab::mechanisms::JansenLengths L = jansen_lengths_of(lengths);
          const double crank = request["crank_angle"];
          CHECK(numlab::mechanisms::JansenLeg(L).closed_form_joints(crank).has_value());
          if (request.contains("theta0") && request["max_iterations"].get<int>() >= 10) {
            numlab::nonlinear::NewtonOptions options;
            options.residual_tolerance = request["tolerance"];
            options.max_iterations = request["max_iterations"];
            const numlab::mechanisms::JansenClosure closure(crank, L);
            const auto solved = numlab::nonlinear::Newton<numlab::mechanisms::JansenClosure>(closure, options)
                                    .solve(numlab::mechanisms::JansenClosure::Vector(
                                        numlab::exercise::vector(request["theta0"]).data()));
            CHECK(solved.status == numlab::Status::converged);
          }
        }
      }
    }
  }
  CHECK(by_id["s1234567"] != by_id["alice"]);
  CHECK(by_id["alice"] != by_id["42"]);
  CHECK(by_id["s1234567"] != by_id["42"]);
}

TEST_CASE("under a variant a solution that ignores the request's lengths (the seed's constants) fails with "
          "diagnosis wrong_link") {
  for (const char* name : {"jansen-jacobian", "jansen10-jacobian", "jansen-newton", "mustang-newton"}) {
    INFO(name);
    const Solve solve = references().at(name).solve;
    FunctionSession session(name, [solve](const nlohmann::json& request) {
      nlohmann::json without = request;
      without.erase("lengths");
      nlohmann::json reply = solve(without);
      reply["id"] = request["id"];
      return reply;
    });
    const auto results = run_checks(find_exercise(name), session, Variant("s1234567"));
    CHECK(results.front().status == CheckStatus::fail);
    const auto diagnosis = overall_diagnosis(results);
    REQUIRE(diagnosis.has_value());
    CHECK(diagnosis->cause == "wrong_link");
    CHECK_THAT(diagnosis->evidence, Catch::Matchers::Contains("lengths"));
  }
}

// Link lengths of mustang-newton (issue 29 §4): a variant's linkage, its limits and its crossing.
namespace {

// Seed 003's lengths by the protocol's names (docs/exercises.md), typed here from the seed.
const std::map<std::string, double>& mustang_seed_lengths() {
  static const std::map<std::string, double> lengths = {
      {"l1_3", 2.0},      {"l3_4", 2.0},       {"l2_4", 2.5},  {"l4_6", 2.5},        {"l0_5", 5.0},
      {"l5_6", 4.0 / 3.0}, {"l6_7", 4.0 / 3.0}, {"l6_8", 4.0},  {"l8_9", 1.0},        {"l7_10", 4.5},
      {"l10_8", 4.0 / 3.0}, {"l10_11", 4.0 / 3.0}, {"l9_11", 1.0}};
  return lengths;
}

numlab::mechanisms::MustangLengths mustang_lengths_of(const nlohmann::json& given) {
  numlab::mechanisms::MustangLengths L;
  L.l1_3 = given["l1_3"], L.l3_4 = given["l3_4"], L.l2_4 = given["l2_4"], L.l4_6 = given["l4_6"];
  L.l0_5 = given["l0_5"], L.l5_6 = given["l5_6"], L.l6_7 = given["l6_7"], L.l6_8 = given["l6_8"];
  L.l8_9 = given["l8_9"], L.l7_10 = given["l7_10"], L.l10_8 = given["l10_8"], L.l10_11 = given["l10_11"];
  L.l9_11 = given["l9_11"];
  return L;
}

bool mustang_assembles(const numlab::mechanisms::MustangLengths& L, double deg) {
  return numlab::mechanisms::MustangLinkage(L).closed_form(deg * std::numbers::pi / 180.0).status ==
         numlab::Status::converged;
}

// The limit between an angle that assembles and one that does not, by bisection to 1e-6 deg.
double mustang_limit(const numlab::mechanisms::MustangLengths& L, double yes, double no) {
  while (std::abs(no - yes) > 1e-6) {
    const double middle = 0.5 * (yes + no);
    (mustang_assembles(L, middle) ? yes : no) = middle;
  }
  return yes;
}

double degrees_of(const nlohmann::json& request) { return request["crank_angle"].get<double>() * 180.0 / std::numbers::pi; }

}  // namespace

TEST_CASE("without a variant no mustang-newton request carries lengths, and its limits are seed 003's") {
  for (const auto& check : requests_of(run("mustang-newton", Variant()))) {
    for (const auto& request : check) CHECK_FALSE(request.contains("lengths"));
  }
  const numlab::mechanisms::MustangLengths seed;
  CHECK(std::abs(mustang_limit(seed, 0.0, -90.0) - -41.4257) < 1e-4);  // TASK.md's -41.4257 ... 56.4540
  CHECK(std::abs(mustang_limit(seed, 45.0, 90.0) - 56.4540) < 1e-4);
}

TEST_CASE("under a variant every mustang-newton request carries the variant's lengths: each within 3% of seed "
          "003's, the bend and the kite kept, other for another ID; the linkage assembles over the checked range "
          "and near both of its own limits, and not beyond them") {
  std::map<std::string, nlohmann::json> by_id;
  for (const char* id : {"s1234567", "alice", "42"}) {
    INFO("mustang-newton under " << id);
    const auto results = run("mustang-newton", Variant(id));
    require_all_pass(results, id);
    const auto requests = requests_of(results);
    REQUIRE(requests.size() == 4);
    const nlohmann::json lengths = requests[0].front()["lengths"];
    by_id[id] = lengths;
    REQUIRE(lengths.size() == 13u);
    for (const auto& [key, value] : lengths.items()) {
      const double seed = mustang_seed_lengths().at(key), drawn = value.get<double>();
      CHECK(std::abs(drawn / seed - 1.0) <= 0.03);
      CHECK(drawn != seed);
    }
    CHECK(lengths["l4_6"] == lengths["l2_4"]);
    CHECK(lengths["l10_11"] == lengths["l10_8"]);
    CHECK(lengths["l9_11"] == lengths["l8_9"]);
    const auto L = mustang_lengths_of(lengths);
    const double lower = mustang_limit(L, 0.0, -90.0), upper = mustang_limit(L, 45.0, 90.0);
    INFO("the variant's linkage assembles on [" << lower << ", " << upper << "] deg");
    CHECK(std::abs(lower - -41.4257) > 0.01);  // its own limits, not the seed's
    CHECK(std::abs(upper - 56.4540) > 0.01);
    double low = 360.0, high = -360.0;
    for (std::size_t k = 0; k < requests.size(); ++k) {
      for (const auto& request : requests[k]) {
        CHECK(request["lengths"] == lengths);  // the same linkage in every request
        const double deg = degrees_of(request);
        if (k == 1) {  // beyond the limits: no pose
          CHECK_FALSE(mustang_assembles(L, deg));
          CHECK((deg < lower || deg > upper));
          continue;
        }
        CHECK(mustang_assembles(L, deg));
        low = std::min(low, deg);
        high = std::max(high, deg);
      }
    }
    // Check 1 goes to within 0.2 deg of each limit; the linkage assembles at every quarter degree between.
    CHECK(low - lower < 0.2);
    CHECK(upper - high < 0.2);
    for (double deg = low; deg <= high; deg += 0.25) CHECK(mustang_assembles(L, deg));
    // numlab's Newton converges from every start of check 1 (the closed form's branch is its business).
    for (const auto& request : requests[0]) {
      numlab::nonlinear::NewtonOptions options;
      options.residual_tolerance = request["tolerance"];
      options.max_iterations = request["max_iterations"];
      const numlab::mechanisms::MustangClosure closure(request["crank_angle"].get<double>(), L);
      const auto solved = numlab::nonlinear::Newton<numlab::mechanisms::MustangClosure>(closure, options)
                              .solve(numlab::mechanisms::MustangClosure::Vector(
                                  numlab::exercise::vector(request["guess"]).data()));
      CHECK(solved.status == numlab::Status::converged);
    }
  }
  CHECK(by_id["s1234567"] != by_id["alice"]);
  CHECK(by_id["alice"] != by_id["42"]);
  CHECK(by_id["s1234567"] != by_id["42"]);
}
