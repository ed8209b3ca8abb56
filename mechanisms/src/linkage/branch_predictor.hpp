#pragma once
// The predictor that carries a continuation through singular poses.
//
// The tangent q' from J q' = -Phi_t is undefined where J is singular, and just past a crossing of
// two branches it is the tangent of whichever branch the last pose happened to land on. Positions
// on the smooth branch are smooth in the driver, so the polynomial through the last solved poses
// continues that branch whatever the grid:
//
//   1. keep the last three solved poses (t0, q0), (t1, q1), (t2, q2), newest last;
//   2. divided differences: d1 = (q2 - q1) / (t2 - t1),  d2 = (d1 - (q1 - q0) / (t1 - t0)) / (t2 - t0);
//   3. predict q(t) = q2 + d1 (t - t2) + d2 (t - t2)(t - t1)   (the quadratic through the three);
//   4. its error is of order |d2 (t - t2)(t - t1)| times (t - t0) / (t2 - t0), and that of the line
//      q2 + d1 (t - t2) is |d2 (t - t2)(t - t1)|: the jump a solved pose may make from the prediction
//      is judged against that, and against the step's own motion |d1 (t - t2)| (d2 vanishes where
//      the motion has an inflection; another branch is a good part of a step's motion away).
//
// Two branches that cross separate linearly in t; the quadratic's error is cubic in the step, so
// near a crossing the prediction is much nearer the smooth branch than the other.
// Every vector is sized once (reset), so predicting allocates nothing.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

namespace numlab::mechanisms::detail {

class BranchPredictor {
 public:
  // Forgets every pose and sizes the workspace for n unknowns.
  void reset(Eigen::Index n) {
    for (auto& q : q_) q.resize(n);
    d1_.resize(n);
    d2_.resize(n);
    count_ = 0;
  }
  void clear() { count_ = 0; }
  int count() const { return count_; }

  // Records a solved pose. A pose at the driver value of a kept one (to rounding: the newest, or an
  // older one when the sweep turns back) replaces it.
  void push(double t, const Eigen::VectorXd& q) {
    for (int i = 0; i < count_; ++i) {
      if (!same_driver(t, t_[static_cast<std::size_t>(i)])) continue;
      for (int j = i; j + 1 < count_; ++j) {  // the older pose goes; the newer ones move down
        t_[static_cast<std::size_t>(j)] = t_[static_cast<std::size_t>(j + 1)];
        q_[static_cast<std::size_t>(j)].swap(q_[static_cast<std::size_t>(j + 1)]);
      }
      --count_;
      break;
    }
    if (count_ == 3) {  // drop the oldest
      std::swap(t_[0], t_[1]);
      std::swap(t_[1], t_[2]);
      q_[0].swap(q_[1]);
      q_[1].swap(q_[2]);
      count_ = 2;
    }
    t_[count_] = t;
    q_[count_] = q;
    ++count_;
  }

  // Whether the quadratic applies at t: three poses, and t no further from the newest than
  // `reach` spacings (far beyond its points a polynomial says little).
  bool quadratic_applies(double t, double reach = 4.0) const {
    if (count_ < 3) return false;
    const double spacing = std::min(std::abs(t_[2] - t_[1]), std::abs(t_[1] - t_[0]));
    return std::abs(t - t_[2]) <= reach * spacing;
  }

  // Steps 2 and 3: the quadratic's prediction at t into q; false (q untouched) when it does not apply.
  // `line_error` receives step 4's estimate, max |d2 (t - t2)(t - t1)|; `motion` the step's own
  // size, max |d1 (t - t2)|.
  bool predict(double t, Eigen::VectorXd& q, double& line_error, double& motion) {
    if (!quadratic_applies(t)) return false;
    d1_ = (q_[2] - q_[1]) / (t_[2] - t_[1]);                                   // 2. divided differences
    d2_ = (d1_ - (q_[1] - q_[0]) / (t_[1] - t_[0])) / (t_[2] - t_[0]);
    const double w1 = t - t_[2], w2 = (t - t_[2]) * (t - t_[1]);
    q = q_[2] + w1 * d1_ + w2 * d2_;                                           // 3. the quadratic
    line_error = d2_.size() == 0 ? 0.0 : std::abs(w2) * d2_.lpNorm<Eigen::Infinity>();  // 4.
    motion = d1_.size() == 0 ? 0.0 : std::abs(w1) * d1_.lpNorm<Eigen::Infinity>();
    return true;
  }

  double newest_driver() const { return t_[newest()]; }
  // Whether the newest pose is at t, to rounding.
  bool newest_at(double t) const { return count_ > 0 && same_driver(t, t_[newest()]); }
  static bool same_driver(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

  // Moves every kept pose by dt in the driver: a crank's poses a whole number of turns away are the
  // same poses.
  void shift(double dt) {
    for (int i = 0; i < count_; ++i) t_[static_cast<std::size_t>(i)] += dt;
  }

 private:
  int newest() const { return count_ - 1; }
  std::array<double, 3> t_{};
  std::array<Eigen::VectorXd, 3> q_;
  Eigen::VectorXd d1_, d2_;
  int count_ = 0;
};

}  // namespace numlab::mechanisms::detail
