#include "numlab/mechanisms/linkage/crank_analysis.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;
constexpr double degrees = 180.0 / pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A moving member: a [[link]] or a [[body]], its joints and its name.
struct Member {
  std::vector<int> joints;
  std::string name;
  const LinkSpec* link = nullptr;
  const BodySpec* body = nullptr;
  bool has(int j) const { return std::find(joints.begin(), joints.end(), j) != joints.end(); }
  // The distance the member holds between two of its joints.
  double distance(int i, int j) const {
    if (link != nullptr) return link->length;
    const auto at = [&](int k) { return body->local[static_cast<std::size_t>(std::find(joints.begin(), joints.end(), k) - joints.begin())]; };
    return (at(i) - at(j)).norm();
  }
};

std::vector<Member> members(const LinkageDescription& d) {
  std::vector<Member> out;
  for (const LinkSpec& link : d.links) out.push_back({{link.first, link.second}, link_name(d, link), &link, nullptr});
  for (const BodySpec& body : d.bodies) out.push_back({body.joints, body_column_name(body, d), nullptr, &body});
  return out;
}

// The joints of `m` other than `except` that are on the ground (ground) or not.
std::vector<int> joints_of(const LinkageDescription& d, const Member& m, bool ground) {
  std::vector<int> out;
  for (int j : m.joints) {
    if (d.joints[static_cast<std::size_t>(j)].ground == ground) out.push_back(j);
  }
  return out;
}

// The toggles' words (std::string once, here: GCC 12 warns falsely on strings built inline from them).
const std::string rod_normal_text = "rod normal to the slider's line";
const std::string extended_text = "crank and coupler extended in line";
const std::string folded_text = "crank and coupler folded in line";
const std::string standing_text = "the output stands still";

Toggle toggle_at(double crank_deg, double closed_form_deg, const std::string& what, bool extended = false) {
  Toggle toggle;
  toggle.crank_deg = crank_deg;
  toggle.closed_form_deg = closed_form_deg;
  toggle.what = what;
  toggle.extended = extended;
  return toggle;
}

double wrap_degrees(double a) {
  a = std::fmod(a, 360.0);
  return a < 0.0 ? a + 360.0 : (a >= 360.0 ? a - 360.0 : a);
}

// The structure, or why it is not one we analyse.
struct Structure {
  int O = -1, A = -1, B = -1, Q = -1;  // B: the rocker's moving end, or the slider's joint
  const Member *crank = nullptr, *coupler = nullptr, *rocker = nullptr;
  std::string problem;
};

Structure find_structure(const LinkageDescription& d, const std::vector<Member>& m) {
  Structure s;
  if (d.driver.kind != DriverKind::crank) return {.problem = "not a four-bar: it is driven by a slider, not a crank"};
  s.O = d.driver.pivot, s.A = d.driver.joint;
  const std::size_t wanted = d.sliders.empty() ? 3 : 2;
  if (d.sliders.size() > 1) return {.problem = "not a four-bar: " + std::to_string(d.sliders.size()) + " sliders"};
  if (m.size() != wanted) {
    return {.problem = "not a four-bar: " + std::to_string(m.size()) + " links and bodies (a four-bar has three, crank, "
                       "coupler and rocker; a slider-crank two, crank and rod)"};
  }
  for (const Member& member : m) {
    if (member.has(s.O) && member.has(s.A)) s.crank = &member;
  }
  for (const Member& member : m) {
    if (&member != s.crank && member.has(s.A)) s.coupler = &member;
  }
  if (s.crank == nullptr || s.coupler == nullptr) return {.problem = "not a four-bar: no coupler on the crank's joint"};
  if (joints_of(d, *s.crank, true).size() != 1 || !joints_of(d, *s.coupler, true).empty()) {
    return {.problem = "not a four-bar: the crank or coupler holds another ground joint"};
  }
  if (!d.sliders.empty()) {
    s.B = d.sliders[0].joint;
    if (!s.coupler->has(s.B) || s.B == s.A) return {.problem = "not a four-bar: the slider is not on the crank's rod"};
    return s;
  }
  for (const Member& member : m) {
    if (&member != s.crank && &member != s.coupler) s.rocker = &member;
  }
  const auto ground = joints_of(d, *s.rocker, true);
  if (ground.size() != 1 || ground[0] == s.O) return {.problem = "not a four-bar: the third member is not a rocker on its own ground pivot"};
  s.Q = ground[0];
  for (int j : s.rocker->joints) {
    if (j != s.Q && j != s.A && s.coupler->has(j)) s.B = j;
  }
  if (s.B < 0) return {.problem = "not a four-bar: the coupler and the rocker share no joint"};
  return s;
}

// A pose at driver t (radians) solved from q0 and polished by Newton to rounding: the roots are
// asked to 1e-10 rad, finer than the sweep's tolerance.
Eigen::VectorXd polished(const LinkageSolver& solver, double t, const Eigen::VectorXd& q0) {
  const LinkageModel& model = solver.model();
  Eigen::VectorXd q = solver.solve(t, q0).q, f;
  Eigen::MatrixXd J;
  for (int k = 0; k < 3; ++k) {
    model.residual(q, t, f);
    model.jacobian(q, t, J);
    q -= Eigen::PartialPivLU<Eigen::MatrixXd>(J).solve(f);
  }
  return q;
}

// Brent's method (GSL) on f over [lo, hi] where f changes sign; the root to 1e-10 in x.
double brent(const std::function<double(double)>& f, double lo, double hi, int& most_iterations) {
  const double f_lo = f(lo), f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) == (f_hi < 0.0)) return nan;  // the sign change did not survive the polish: no root
  gsl_set_error_handler_off();  // GSL's default handler aborts; a failure is a NaN here
  gsl_function F;
  F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  F.params = const_cast<std::function<double(double)>*>(&f);
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double root = nan;
  if (gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS) {
    for (int k = 1; k <= 200; ++k) {
      if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
      if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 1e-10, 0.0) == GSL_SUCCESS) {
        root = gsl_root_fsolver_root(s);
        most_iterations = std::max(most_iterations, k);
        break;
      }
    }
  }
  gsl_root_fsolver_free(s);
  return root;
}

// Roots of g over a full turn of the crank (radians), bracketed on a 1-degree grid.
std::vector<double> roots_over_turn(const std::function<double(double)>& g, int& iterations) {
  std::vector<double> roots;
  const int n = 360;
  double previous = g(0.0);
  for (int k = 1; k <= n; ++k) {
    const double lo = (k - 1) * 2.0 * pi / n, hi = k * 2.0 * pi / n, value = g(hi);
    if ((previous < 0.0) != (value < 0.0) || value == 0.0) {
      const double root = brent(g, lo, hi, iterations);
      if (std::isfinite(root) && (roots.empty() || std::abs(root - roots.back()) > 1e-9)) roots.push_back(root);
    }
    previous = value;
  }
  return roots;
}

// The closed form nearest to `found` among the candidates (degrees), or NaN.
double nearest(double found, const std::vector<double>& candidates) {
  double best = nan, gap = 1e300;
  for (double c : candidates) {
    if (!std::isfinite(c)) continue;
    const double g = std::abs(wrap_degrees(c - found + 180.0) - 180.0);
    if (g < gap) gap = g, best = wrap_degrees(c);
  }
  return best;
}

class Analyser {
 public:
  Analyser(const LinkageSolver& solver, const std::string& output_name)
      : solver_(solver), model_(solver.model()), d_(model_.description()), lines_(link_lines(d_)) {
    members_ = members(d_);
    s_ = find_structure(d_, members_);
    if (!output_name.empty()) {
      const auto output = find_output(d_, output_name);
      if (!output) throw std::invalid_argument("unknown output '" + output_name + "': name one of the " + output_choices(d_));
      output_ = *output;
    }
  }

  CrankAnalysis run() {
    CrankAnalysis r;
    if (!s_.problem.empty()) {
      r.not_analysed = s_.problem;
      return r;
    }
    const auto P = [&](int j) { return d_.joints[static_cast<std::size_t>(j)].position; };
    r.crank_name = s_.crank->name;
    r.coupler_name = s_.coupler->name;
    r.crank = s_.crank->distance(s_.O, s_.A);
    r.coupler = s_.coupler->distance(s_.A, s_.B);
    if (s_.rocker != nullptr) {
      r.kind = "four-bar";
      r.rocker_name = s_.rocker->name;
      r.rocker = s_.rocker->distance(s_.Q, s_.B);
      r.ground = (P(s_.Q) - P(s_.O)).norm();
      classify(r);
      if (output_.name.empty()) output_ = *find_output(d_, r.rocker_name);
    } else {
      r.kind = "slider-crank";
      const SliderSpec& slider = d_.sliders[0];
      const double angle = slider.angle_deg / degrees;
      const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), w = slider.through - P(s_.O);
      r.ground = u.x() * w.y() - u.y() * w.x();  // the offset e: the line's signed distance from O
      r.crank_turns_fully = r.crank + std::abs(r.ground) <= r.coupler;
      r.classification = r.crank_turns_fully ? "the crank turns fully (r + |e| <= l)" : "the crank cannot turn fully (r + |e| > l)";
      if (output_.name.empty()) output_ = *find_output(d_, d_.joints[static_cast<std::size_t>(s_.B)].name);
    }
    r.output = output_.name;
    driver_toggles(r);
    output_toggles(r);
    time_ratio(r);
    r.brent_iterations = iterations_;
    return r;
  }

 private:
  Eigen::Vector2d ground(int j) const { return d_.joints[static_cast<std::size_t>(j)].position; }

  void classify(CrankAnalysis& r) const {
    const std::pair<double, const char*> links[] = {{r.crank, "crank"}, {r.ground, "ground"}, {r.rocker, "rocker"}, {r.coupler, "coupler"}};
    const auto* s = &links[0];
    const auto* l = &links[0];
    for (const auto& link : links) {
      if (link.first < s->first) s = &link;
      if (link.first > l->first) l = &link;
    }
    r.shortest = s->first, r.longest = l->first;
    r.others = r.crank + r.coupler + r.rocker + r.ground - r.shortest - r.longest;
    r.shortest_name = s->second;
    const double sum = r.shortest + r.longest, scale = r.longest;
    r.grashof = sum <= r.others + 1e-12 * scale;
    if (std::abs(sum - r.others) <= 1e-12 * scale) {
      r.classification = "change point";
    } else if (!r.grashof) {
      r.classification = "triple-rocker (non-Grashof)";
    } else {
      const char* kinds[] = {"crank-rocker", "double-crank", "rocker-crank", "double-rocker"};  // by links' order
      r.classification = kinds[s - &links[0]];
    }
  }

  // The crank's own dead centres: the coupler and rocker in line, |AQ| = b + c or |b - c|.
  void driver_toggles(CrankAnalysis& r) {
    if (s_.rocker == nullptr) {
      // The rod normal to the line: |e - r sin| = l, which needs r + |e| >= l.
      // The rod's end S is e - r sin(t - beta) from the line through A parallel to the slider's.
      const auto g = [&](double sign) {
        return [&, sign](double t) { return sign * (r.ground - r.crank * std::sin(t - slider_angle())) - r.coupler; };
      };
      for (double sign : {1.0, -1.0}) {
        for (double t : roots_over_turn(g(sign), iterations_)) {
          r.driver_toggles.push_back(toggle_at(wrap_degrees(t * degrees), nan, rod_normal_text));
        }
      }
      sort(r.driver_toggles);
      return;
    }
    const Eigen::Vector2d O = ground(s_.O), Q = ground(s_.Q);
    const double gamma = std::atan2(Q.y() - O.y(), Q.x() - O.x());
    static const std::string coupler_rocker[] = {"coupler and rocker extended in line", "coupler and rocker folded in line"};
    for (const auto& [length, what] : {std::pair{r.coupler + r.rocker, &coupler_rocker[0]},
                                      std::pair{std::abs(r.coupler - r.rocker), &coupler_rocker[1]}}) {
      const auto g = [&, length = length](double t) {
        return (O + r.crank * Eigen::Vector2d(std::cos(t), std::sin(t)) - Q).norm() - length;
      };
      const double c = (r.crank * r.crank + r.ground * r.ground - length * length) / (2.0 * r.crank * r.ground);
      const double phi = std::abs(c) <= 1.0 ? std::acos(c) : nan;
      for (double t : roots_over_turn(g, iterations_)) {
        const double found = wrap_degrees(t * degrees);
        r.driver_toggles.push_back(toggle_at(found, nearest(found, {(gamma + phi) * degrees, (gamma - phi) * degrees}), *what));
      }
    }
    sort(r.driver_toggles);
    r.crank_turns_fully = r.driver_toggles.empty();
  }

  double slider_angle() const { return d_.sliders[0].angle_deg / degrees; }

  // The output's rate d(output)/d(crank) at a pose.
  double rate(double t, const Eigen::VectorXd& q) const {
    const auto joints = joint_motions(model_, q, linkage_velocity(model_, t, q), Eigen::VectorXd());
    return output_rate(output_, lines_, joints);
  }

  // Where the output's rate changes sign over the reference branch: a sweep each way from the
  // reference pose (a full turn, or up to the crank's own toggles), then Brent on each bracket.
  void output_toggles(CrankAnalysis& r) {
    const double reference = model_.driver_to_user(solver_.reference_driver());
    for (const double stop : {reference + 360.0, reference - 360.0}) {
      if (r.crank_turns_fully && stop < reference) break;  // one turn covers it
      const LinkageSweep sweep = linkage_sweep(solver_, reference, stop, stop > reference ? 1.0 : -1.0);
      const LinkagePose* previous = nullptr;
      double previous_rate = nan;
      for (const LinkagePose& pose : sweep.poses) {
        if (pose.outcome.status != Status::converged || pose.velocity.size() == 0) break;
        const double t = model_.driver_from_user(pose.driver), value = rate(t, pose.q);
        if (previous != nullptr && ((previous_rate < 0.0) != (value < 0.0))) {
          const Eigen::VectorXd start = previous->q;
          const auto f = [&](double x) { return rate(x, polished(solver_, x, start)); };
          const double t0 = model_.driver_from_user(previous->driver);
          const double root = brent(f, std::min(t0, t), std::max(t0, t), iterations_);
          if (std::isfinite(root)) add_output_toggle(r, wrap_degrees(model_.driver_to_user(root)), polished(solver_, root, start));
        }
        previous = &pose, previous_rate = value;
      }
    }
    sort(r.output_toggles);
    add_closed_forms(r);
  }

  // A toggle at `found` degrees, the pose q there: crank and coupler (rod) extended or folded.
  void add_output_toggle(CrankAnalysis& r, double found, const Eigen::VectorXd& q) const {
    for (const Toggle& t : r.output_toggles) {
      if (std::abs(wrap_degrees(t.crank_deg - found + 180.0) - 180.0) < 1e-7) return;  // the turn's two ends
    }
    const Eigen::Vector2d O = ground(s_.O);
    const Eigen::Vector2d A = model_.positions(q)[static_cast<std::size_t>(s_.A)], B = model_.positions(q)[static_cast<std::size_t>(s_.B)];
    const bool extended = (A - O).dot(B - A) > 0.0;
    r.output_toggles.push_back(toggle_at(found, nan, extended ? extended_text : folded_text, extended));
  }


  // The textbook's positions: crank and coupler (rod) extended or folded in line, for the default output.
  void add_closed_forms(CrankAnalysis& r) const {
    const bool default_output = s_.rocker != nullptr ? output_.line >= 0 && lines_[static_cast<std::size_t>(output_.line)].name == s_.rocker->name
                                                     : output_.joint == s_.B;
    const Eigen::Vector2d O = ground(s_.O);
    for (Toggle& toggle : r.output_toggles) {
      const bool extended = toggle.extended;
      if (!default_output) {
        toggle.what = standing_text;
        continue;
      }
      std::vector<double> candidates;
      if (s_.rocker != nullptr) {
        const Eigen::Vector2d Q = ground(s_.Q);
        const double gamma = std::atan2(Q.y() - O.y(), Q.x() - O.x());
        const double reach = extended ? r.coupler + r.crank : std::abs(r.coupler - r.crank);
        const double c = (r.ground * r.ground + reach * reach - r.rocker * r.rocker) / (2.0 * r.ground * reach);
        const double phi = std::acos(std::clamp(c, -1.0, 1.0)), turn = extended ? 0.0 : pi;
        candidates = {(gamma + phi + turn) * degrees, (gamma - phi + turn) * degrees};
      } else {
        const double beta = slider_angle(), reach = extended ? r.coupler + r.crank : std::abs(r.coupler - r.crank);
        const double along = std::sqrt(std::max(0.0, reach * reach - r.ground * r.ground)), turn = extended ? 0.0 : pi;
        candidates = {(beta + std::atan2(r.ground, along) + turn) * degrees, (beta + std::atan2(r.ground, -along) + turn) * degrees};
      }
      toggle.closed_form_deg = nearest(toggle.crank_deg, candidates);
    }
  }

  void time_ratio(CrankAnalysis& r) const {
    if (!r.crank_turns_fully || r.output_toggles.size() != 2) return;
    const double stroke = wrap_degrees(r.output_toggles[1].crank_deg - r.output_toggles[0].crank_deg);
    r.alpha_deg = std::abs(stroke - 180.0);
    r.time_ratio = (180.0 + r.alpha_deg) / (180.0 - r.alpha_deg);
    const double a = r.output_toggles[0].closed_form_deg, b = r.output_toggles[1].closed_form_deg;
    if (std::isfinite(a) && std::isfinite(b)) {
      const double alpha = std::abs(wrap_degrees(b - a) - 180.0);
      r.time_ratio_closed_form = (180.0 + alpha) / (180.0 - alpha);
    }
  }

  static void sort(std::vector<Toggle>& toggles) {
    std::sort(toggles.begin(), toggles.end(), [](const Toggle& a, const Toggle& b) { return a.crank_deg < b.crank_deg; });
  }

  const LinkageSolver& solver_;
  const LinkageModel& model_;
  const LinkageDescription& d_;
  std::vector<LinkLine> lines_;
  std::vector<Member> members_;
  Structure s_;
  LinkageOutput output_;
  int iterations_ = 0;
};

}  // namespace

CrankAnalysis analyse_crank_mechanism(const LinkageSolver& solver, const std::string& output) {
  return Analyser(solver, output).run();
}

}  // namespace numlab::mechanisms
