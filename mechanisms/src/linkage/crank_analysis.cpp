#include "numlab/mechanisms/linkage/crank_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include <fmt/format.h>

#include "crank_roots.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"

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
  if (d.driver.kind != DriverKind::crank) {
    constexpr const char* kinds[] = {"a crank", "a slider", "an actuator", "a motor"};
    return {.problem = std::string("not a four-bar: it is driven by ") + kinds[static_cast<int>(d.driver.kind)] + ", not a crank"};
  }
  if (std::any_of(d.sliders.begin(), d.sliders.end(), [](const SliderSpec& slider) { return slider.on_link(); })) {
    return {.problem = "not a four-bar or slider-crank: a slider runs on a moving link"};
  }
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

using crank_roots::half_turn_roots;

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
    const std::string& name = output_name.empty() ? d_.output : output_name;  // --output, else the file's
    if (!name.empty()) {
      const auto output = find_output(d_, name);
      if (!output) throw std::invalid_argument("unknown output '" + name + "': name one of the " + output_choices(d_));
      output_ = *output;
    }
  }

  CrankAnalysis run() {
    CrankAnalysis r;
    if (!s_.problem.empty()) {
      r.not_analysed = s_.problem;
      if (d_.driver.kind != DriverKind::crank) return r;
      if (output_.name.empty()) {
        r.not_analysed += "; name an output (--output or the file's output) for its toggles and time ratio";
        return r;
      }
      return crank_driven(r);
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
      r.classification = r.crank + std::abs(r.ground) <= r.coupler ? "the crank turns fully (r + |e| <= l)"
                                                                   : "the crank cannot turn fully (r + |e| > l)";
      if (output_.name.empty()) output_ = *find_output(d_, d_.joints[static_cast<std::size_t>(s_.B)].name);
    }
    r.output = output_.name;
    r.output_is_angle = output_.angle();
    driver_toggles(r);
    output_toggles(r);
    add_closed_forms(r);
    time_ratio(r);
    r.brent_iterations = iterations_;
    return r;
  }

 private:
  Eigen::Vector2d ground(int j) const { return d_.joints[static_cast<std::size_t>(j)].position; }
  double reference() const { return model_.driver_to_user(solver_.reference_driver()); }

  // Any other crank-driven mechanism, by its output alone: the crank a turn from the reference pose
  // (it turns fully when every pose of the turn assembles), the output's toggles over it, the time ratio.
  CrankAnalysis crank_driven(CrankAnalysis& r) {
    r.kind = "crank-driven";
    r.output = output_.name;
    r.output_is_angle = output_.angle();
    for (const Member& m : members_) {
      if (m.has(d_.driver.pivot) && m.has(d_.driver.joint)) r.crank_name = m.name, r.crank = m.distance(d_.driver.pivot, d_.driver.joint);
    }
    double reached = reference();
    add_rate_roots(r, reference() + 360.0, reached);
    r.crank_turns_fully = reached >= reference() + 360.0 - 1e-9;
    if (r.crank_turns_fully) {
      r.classification = "the crank turns fully (every pose of a turn assembles)";
    } else {
      const double upper = reached;
      add_rate_roots(r, reference() - 360.0, reached);
      r.classification = fmt_range(reached, upper);
    }
    sort(r.output_toggles);
    for (Toggle& t : r.output_toggles) t.what = standing_text;
    time_ratio(r);
    r.brent_iterations = iterations_;
    return r;
  }

  static std::string fmt_range(double lo, double hi) {
    return fmt::format("the crank does not turn fully: from the reference pose it assembles from {:.6f} to {:.6f} deg", lo, hi);
  }

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

  // The crank's own dead centres, where it cannot turn on. The velocity ratio is infinite there (a
  // fold: no pose past it), so the root is taken of a smooth function of the crank angle t instead.
  void driver_toggles(CrankAnalysis& r) {
    const double flat = 1e-12 * std::max({r.crank, r.coupler, r.rocker, std::abs(r.ground)});
    if (s_.rocker == nullptr) {
      // 1. Slider-crank: the rod normal to the line, h(t) = e - r sin(t - beta) = +-l (h: the line's
      //    distance from A), monotone on the half-turns from beta - 90 deg; sin(t - beta) = (e -+ l) / r.
      const double beta = slider_angle();
      for (const double h : {r.coupler, -r.coupler}) {
        const auto g = [&, h](double t) { return r.ground - r.crank * std::sin(t - beta) - h; };
        const double s = (r.ground - h) / r.crank, phi = std::abs(s) <= 1.0 ? std::asin(s) : nan;
        for (double t : half_turn_roots(g, beta - pi / 2.0, flat, iterations_)) {
          const double found = wrap_degrees(t * degrees);
          r.driver_toggles.push_back(toggle_at(found, nearest(found, {(beta + phi) * degrees, (beta + pi - phi) * degrees}), rod_normal_text));
        }
      }
      sort(r.driver_toggles);
      r.crank_turns_fully = r.driver_toggles.empty();
      return;
    }
    // 2. Four-bar: |AQ(t)| = b + c (extended) or |b - c| (folded); |AQ|^2 = a^2 + d^2 - 2ad cos(t - gamma)
    //    grows on [gamma, gamma + pi] and falls on [gamma + pi, gamma + 2 pi]: one bracket each.
    const Eigen::Vector2d O = ground(s_.O), Q = ground(s_.Q);
    const double gamma = std::atan2(Q.y() - O.y(), Q.x() - O.x());
    static const std::string coupler_rocker[] = {"coupler and rocker extended in line", "coupler and rocker folded in line"};
    for (const auto& [length, what] : {std::pair{r.coupler + r.rocker, &coupler_rocker[0]},
                                      std::pair{std::abs(r.coupler - r.rocker), &coupler_rocker[1]}}) {
      const auto g = [&, length = length](double t) {
        return (O + r.crank * Eigen::Vector2d(std::cos(t), std::sin(t)) - Q).norm() - length;
      };
      // 3. Beside each root, the law of cosines: cos(t - gamma) = (a^2 + d^2 - L^2) / 2ad.
      const double c = (r.crank * r.crank + r.ground * r.ground - length * length) / (2.0 * r.crank * r.ground);
      const double phi = std::abs(c) <= 1.0 ? std::acos(c) : nan;
      for (double t : half_turn_roots(g, gamma, flat, iterations_)) {
        const double found = wrap_degrees(t * degrees);
        r.driver_toggles.push_back(toggle_at(found, nearest(found, {(gamma + phi) * degrees, (gamma - phi) * degrees}), *what));
      }
    }
    sort(r.driver_toggles);
    r.crank_turns_fully = r.driver_toggles.empty();
  }

  double slider_angle() const { return d_.sliders[0].angle_deg / degrees; }

  // The output's toggles from `reference()` towards `stop` (user degrees), added to r.output_toggles.
  void add_rate_roots(CrankAnalysis& r, double stop, double& reached) {
    for (const crank_roots::RateRoot& root : crank_roots::rate_roots_over_sweep(solver_, output_, reference(), stop, iterations_, reached)) {
      add_output_toggle(r, wrap_degrees(root.crank_deg), root.q);
    }
  }

  // Where the output's rate changes sign on the reference branch: a turn from the reference pose, or
  // when the crank does not turn fully, each way up to its nearest toggle (no pose lies past it).
  void output_toggles(CrankAnalysis& r) {
    double reached = 0.0;
    if (r.crank_turns_fully) {
      add_rate_roots(r, reference() + 360.0, reached);
    } else {
      double up = reference() + 360.0, down = reference() - 360.0;
      for (const Toggle& t : r.driver_toggles) {
        up = std::min(up, reference() + wrap_degrees(t.crank_deg - reference()));
        down = std::max(down, reference() - wrap_degrees(reference() - t.crank_deg));
      }
      add_rate_roots(r, up, reached);
      add_rate_roots(r, down, reached);
    }
    sort(r.output_toggles);
  }

  // A toggle at `found` degrees, the pose q there: the output's value, and for a four-bar or
  // slider-crank whether crank and coupler (rod) are extended or folded.
  void add_output_toggle(CrankAnalysis& r, double found, const Eigen::VectorXd& q) const {
    for (const Toggle& t : r.output_toggles) {
      if (std::abs(wrap_degrees(t.crank_deg - found + 180.0) - 180.0) < 1e-7) return;  // the turn's two ends
    }
    const JointPositions p = model_.positions(q);
    Toggle toggle = toggle_at(found, nan, standing_text);
    if (output_.angle()) {
      const LinkLine& line = lines_[static_cast<std::size_t>(output_.line)];
      const Eigen::Vector2d v = p[static_cast<std::size_t>(line.to)] - p[static_cast<std::size_t>(line.from)];
      toggle.output_value = std::atan2(v.y(), v.x()) * degrees;
    } else {
      toggle.output_value = output_.direction.dot(p[static_cast<std::size_t>(output_.joint)]);
    }
    if (s_.problem.empty()) {
      const Eigen::Vector2d O = ground(s_.O), A = p[static_cast<std::size_t>(s_.A)], B = p[static_cast<std::size_t>(s_.B)];
      toggle.extended = (A - O).dot(B - A) > 0.0;
      toggle.what = toggle.extended ? extended_text : folded_text;
    }
    r.output_toggles.push_back(toggle);
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

  // Two toggles t0 < t1 of a crank that turns fully: the crank turns t1 - t0 from the first to the
  // second and 360 - (t1 - t0) back; the slow stroke is the longer, time ratio slow / quick.
  void time_ratio(CrankAnalysis& r) const {
    if (!r.crank_turns_fully || r.output_toggles.size() != 2) return;
    const double stroke = wrap_degrees(r.output_toggles[1].crank_deg - r.output_toggles[0].crank_deg);
    r.slow_stroke_deg = std::max(stroke, 360.0 - stroke);
    r.quick_stroke_deg = 360.0 - r.slow_stroke_deg;
    r.slow_stroke_start = stroke >= 180.0 ? 0 : 1;
    r.alpha_deg = r.slow_stroke_deg - 180.0;
    r.time_ratio = r.slow_stroke_deg / r.quick_stroke_deg;
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
