// The linkage exercise's detectors (labs/exercises/linkage_detectors.hpp) on constructed wrong f and
// J of the shipped four-bar at three poses off its reference: each names its cause, none fires on
// numlab's own f and J, with rounding in every entry or without.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>
#include <string>

#include "exercises/linkage_detectors.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"

using namespace numlab::exercises;
using numlab::mechanisms::LinkageModel;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

LinkageModel four_bar() {
  return LinkageModel(numlab::mechanisms::read_linkage_description(std::string(NUMLAB_MODELS_DIR) + "/four-bar.toml"));
}

// numlab's f and J at three crank angles, q the reference pose moved a little (f is not zero: every
// row counts), the student's f and J set to numlab's.
std::vector<LinkageClosureSample> samples(const LinkageModel& model) {
  std::vector<LinkageClosureSample> out;
  const Eigen::VectorXd q0 = model.unknowns(model.rough_positions());
  for (const double degrees : {40.0, 75.0, 130.0}) {
    LinkageClosureSample s;
    s.driver_user = degrees;
    s.t = model.driver_from_user(degrees);
    s.q = q0 + Eigen::VectorXd::LinSpaced(q0.size(), 0.1, 0.1 * static_cast<double>(q0.size()));
    model.residual(s.q, s.t, s.f_expected);
    s.J_expected = Eigen::MatrixXd::Zero(model.equation_count(), model.unknown_count());
    model.jacobian(s.q, s.t, s.J_expected);
    s.f = s.f_expected;
    s.J = s.J_expected;
    out.push_back(s);
  }
  return out;
}

std::vector<double> tolerances(const std::vector<LinkageClosureSample>& samples) {
  std::vector<double> t;
  for (const auto& s : samples) t.push_back(1e3 * eps * s.J_expected.cwiseAbs().maxCoeff());
  return t;
}

std::string J_cause(const LinkageModel& model, const std::vector<LinkageClosureSample>& samples) {
  const auto diagnosis = diagnose(linkage_J_detectors(model, samples, tolerances(samples)));
  return diagnosis ? diagnosis->cause : "(none)";
}

std::string f_cause(const LinkageModel& model, const std::vector<LinkageClosureSample>& samples) {
  const auto diagnosis = diagnose(linkage_f_detectors(model, samples, 1e3 * eps * 10.0));
  return diagnosis ? diagnosis->cause : "(none)";
}

// The first entry above the diagonal whose mirror differs from it by more than rounding at every pose.
std::pair<int, int> asymmetric_pair(const std::vector<LinkageClosureSample>& samples) {
  const Eigen::MatrixXd& J = samples.front().J_expected;
  for (int i = 0; i < J.rows(); ++i) {
    for (int k = i + 1; k < J.cols(); ++k) {
      bool everywhere = true;
      for (const auto& s : samples) everywhere = everywhere && std::abs(s.J_expected(i, k) - s.J_expected(k, i)) > 1e-3;
      if (everywhere) return {i, k};
    }
  }
  FAIL("the four-bar's J is symmetric");
  return {-1, -1};
}

}  // namespace

TEST_CASE("linkage detectors: none fires on numlab's own f and J, nor on them with rounding in every entry") {
  const LinkageModel model = four_bar();
  auto s = samples(model);
  CHECK(f_cause(model, s) == "(none)");
  CHECK(J_cause(model, s) == "(none)");
  for (auto& sample : s) {
    sample.f *= 1.0 + 4 * eps;
    sample.J *= 1.0 + 4 * eps;
  }
  CHECK(f_cause(model, s) == "(none)");
  CHECK(J_cause(model, s) == "(none)");
}

TEST_CASE("linkage detectors: a J of central differences of f is named, with how far it is from analytic") {
  const LinkageModel model = four_bar();
  auto s = samples(model);
  for (auto& sample : s) {
    const double h = 1e-4;  // a step a student might take: error O(h^2) in J, far above rounding
    Eigen::VectorXd plus(sample.f.size()), minus(sample.f.size());
    for (Eigen::Index k = 0; k < sample.q.size(); ++k) {
      Eigen::VectorXd q = sample.q;
      q(k) += h;
      model.residual(q, sample.t, plus);
      q(k) -= 2 * h;
      model.residual(q, sample.t, minus);
      sample.J.col(k) = (plus - minus) / (2 * h);
    }
  }
  const double worst = (s.front().J - s.front().J_expected).cwiseAbs().maxCoeff();
  REQUIRE(worst > tolerances(s).front());  // the check this J fails
  const auto diagnosis = diagnose(linkage_J_detectors(model, s, tolerances(s)));
  REQUIRE(diagnosis);
  CHECK(diagnosis->cause == "finite_difference_jacobian");
  CHECK_THAT(diagnosis->evidence, Catch::Matchers::Contains("not to rounding"));
}

TEST_CASE("linkage detectors: J transposed, one pair J[i][k] <-> J[k][i] swapped, entries with the opposite sign") {
  const LinkageModel model = four_bar();
  auto transposed = samples(model);
  for (auto& s : transposed) s.J = s.J_expected.transpose();
  CHECK(J_cause(model, transposed) == "transposed_jacobian");

  REQUIRE(transposed.front().J.rows() == transposed.front().J.cols());
  auto swapped = samples(model);
  const auto [i, k] = asymmetric_pair(swapped);
  for (auto& s : swapped) std::swap(s.J(i, k), s.J(k, i));
  const auto diagnosis = diagnose(linkage_J_detectors(model, swapped, tolerances(swapped)));
  REQUIRE(diagnosis);
  CHECK(diagnosis->cause == "transposed_pair");
  CHECK_THAT(diagnosis->evidence, Catch::Matchers::Contains("J[" + std::to_string(i) + "][" + std::to_string(k) + "] and J[" + std::to_string(k) + "][" + std::to_string(i) + "]"));

  auto negated = samples(model);
  for (auto& s : negated) {
    s.J(i, k) = -s.J(i, k);
    s.J(k, i) = -s.J(k, i);
  }
  CHECK(J_cause(model, negated) == "derivative_sign");

  // A row scaled by 2 is neither a sign nor a swap.
  auto scaled = samples(model);
  for (auto& s : scaled) s.J.row(i) *= 2.0;
  CHECK(J_cause(model, scaled) != "derivative_sign");
  CHECK(J_cause(model, scaled) != "transposed_pair");
}

TEST_CASE("linkage detectors: one row of f with the opposite sign") {
  const LinkageModel model = four_bar();
  auto s = samples(model);
  for (auto& sample : s) sample.f(1) = -sample.f(1);
  REQUIRE(s.front().f_expected.cwiseAbs().minCoeff() > 1e-3);
  CHECK(f_cause(model, s) == "f_sign");
}
