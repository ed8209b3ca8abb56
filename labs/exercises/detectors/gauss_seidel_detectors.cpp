#include "exercises/detectors/gauss_seidel_detectors.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "exercises/detectors/explains.hpp"

namespace numlab::exercises::detectors {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Swept {
  Eigen::MatrixXd M;
  Eigen::VectorXd c;
};

// M and c of `system`; nothing when it cannot be formed (A A^T of a matrix that is not square).
std::optional<Swept> swept(const GaussSeidelProblem& p, SweptSystem system) {
  const bool square = p.A.rows() == p.A.cols();
  switch (system) {
    case SweptSystem::asked: return swept(p, p.normal_equations ? SweptSystem::normal : SweptSystem::plain);
    case SweptSystem::plain:
      if (!square) return std::nullopt;
      return Swept{p.A, p.b};
    case SweptSystem::normal: return Swept{p.A.transpose() * p.A, p.A.transpose() * p.b};
    case SweptSystem::a_at:
      if (!square) return std::nullopt;
      return Swept{p.A * p.A.transpose(), p.A.transpose() * p.b};
  }
  return std::nullopt;
}

Eigen::VectorXd sweep(const Swept& s, Eigen::VectorXd x, SweepKind kind) {
  if (kind == SweepKind::no_update) return x;
  const Eigen::VectorXd old = x;
  const Eigen::Index n = x.size();
  for (Eigen::Index step = 0; step < n; ++step) {
    const Eigen::Index i = kind == SweepKind::reverse ? n - 1 - step : step;
    const Eigen::VectorXd& used = kind == SweepKind::jacobi ? old : x;
    x(i) = (s.c(i) - s.M.row(i).dot(used) + s.M(i, i) * used(i)) / s.M(i, i);
  }
  return x;
}

// The residual a residual stop rule tests; 0 for the other rules.
double residual(StopRule rule, const GaussSeidelProblem& p, const Swept& s, const Eigen::VectorXd& x) {
  switch (rule) {
    case StopRule::residual_inf: return (s.c - s.M * x).cwiseAbs().maxCoeff();
    case StopRule::residual_two: return (s.c - s.M * x).norm();
    case StopRule::original_residual_inf: return (p.b - p.A * x).cwiseAbs().maxCoeff();
    case StopRule::original_residual_two: return (p.b - p.A * x).norm();
    default: return 0.0;
  }
}

bool residual_rule(StopRule rule) {
  return rule == StopRule::residual_inf || rule == StopRule::residual_two || rule == StopRule::original_residual_inf ||
         rule == StopRule::original_residual_two;
}

bool stops(StopRule rule, const Eigen::VectorXd& x, const Eigen::VectorXd& old, double update, double tolerance,
           double residual) {
  const double size = x.cwiseAbs().maxCoeff();
  if (residual_rule(rule)) return residual <= tolerance;
  switch (rule) {
    case StopRule::signed_change: return (x - old).maxCoeff() < tolerance;
    case StopRule::absolute: return update <= tolerance;
    case StopRule::relative: return update <= tolerance * size;
    default: return update <= tolerance * std::max(1.0, size);
  }
}

// One sweep as a hypothesis: what it computes, in words, and the remedy.
struct SweepHypothesis {
  const char* cause;
  SweptSystem system;
  SweepKind kind;
  const char* what;
  const char* remedy;
};

std::vector<SweepHypothesis> sweep_hypotheses(const GaussSeidelProblem& p) {
  std::vector<SweepHypothesis> list = {
      {"x_never_updated", SweptSystem::asked, SweepKind::no_update, "a sweep that leaves x as it was",
       "assign x_i inside the sweep, and carry the new x to the next sweep and the reply"},
      {"jacobi_sweep", SweptSystem::asked, SweepKind::jacobi, "a Jacobi sweep (every x_j from the sweep before)",
       "x_i must use the x_j already updated in this sweep (j < i)"},
      {"reverse_order", SweptSystem::asked, SweepKind::reverse, "a sweep from the last equation to the first",
       "sweep the equations in order, i = 0, 1, ..., n-1"},
  };
  if (p.normal_equations) {
    list.push_back({"plain_when_normal_asked", SweptSystem::plain, SweepKind::gauss_seidel,
                    "a Gauss-Seidel sweep of A x = b", "with normal_equations true, sweep M = A^T A and c = A^T b"});
    list.push_back({"a_at_instead_of_at_a", SweptSystem::a_at, SweepKind::gauss_seidel,
                    "a Gauss-Seidel sweep of A A^T x = A^T b", "M = A^T A: A transposed on the left"});
  } else {
    list.push_back({"normal_when_plain_asked", SweptSystem::normal, SweepKind::gauss_seidel,
                    "a Gauss-Seidel sweep of A^T A x = A^T b",
                    "with normal_equations false, sweep A x = b itself"});
  }
  return list;
}

struct StopHypothesis {
  const char* cause;
  StopRule rule;
  const char* what;
  const char* remedy;
};

const char* const update_not_residual =
    "the task's stop test is on the sweep's update, max_i |x_i(new) - x_i(old)| <= tolerance * max(1, max_i |x_i|), "
    "not on the residual";

const std::vector<StopHypothesis> stop_hypotheses = {
    {"limit_reported_converged", StopRule::limit_converged, "reporting the sweep limit as converged",
     "when max_iterations sweeps pass without the stop test passing, the status is max_iterations"},
    {"one_iteration_too_many", StopRule::extra_sweep, "a loop that runs max_iterations + 1 sweeps",
     "stop after max_iterations sweeps (while sweep < max_iterations, counting from 0)"},
    {"stop_test", StopRule::signed_change, "the stop test without abs, max_i (x_i(new) - x_i(old)) < tolerance",
     "compare max_i |x_i(new) - x_i(old)| with tolerance * max(1, max_i |x_i|)"},
    {"stop_test", StopRule::absolute, "the stop test update_inf <= tolerance, without max(1, |x|)",
     "compare update_inf with tolerance * max(1, max_i |x_i|)"},
    {"stop_test", StopRule::relative, "the stop test update_inf <= tolerance * |x|, without max(1, ...)",
     "compare update_inf with tolerance * max(1, max_i |x_i|)"},
    {"stop_test", StopRule::residual_inf, "the stop test on the residual, max_i |c - M x| <= tolerance",
     update_not_residual},
    {"stop_test", StopRule::residual_two, "the stop test on the residual, ||c - M x||_2 <= tolerance",
     update_not_residual},
    {"stop_test", StopRule::original_residual_inf, "the stop test on the residual of A x = b, max_i |b - A x| <= tolerance",
     update_not_residual},
    {"stop_test", StopRule::original_residual_two, "the stop test on the residual of A x = b, ||b - A x||_2 <= tolerance",
     update_not_residual},
};

double row_amplification(const Eigen::MatrixXd& M) {
  double largest = 1.0;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    largest = std::max(largest, M.row(i).cwiseAbs().sum() / std::abs(M(i, i)));
  }
  return largest;
}

std::string ending(const std::string& status, long long sweeps) {
  return fmt::format("\"{}\" after {} sweep{}", status, sweeps, sweeps == 1 ? "" : "s");
}

// The first sweep of the student's trace that departs from numlab's, with the check's tolerance.
std::optional<std::size_t> first_departing_sweep(const GaussSeidelRun& reference,
                                                 const std::vector<GaussSeidelSweep>& trace, double n) {
  double largest = 1.0;
  for (const Eigen::VectorXd& x : reference.xs) largest = std::max(largest, x.cwiseAbs().maxCoeff());
  const std::size_t common = std::min(trace.size(), reference.xs.size());
  for (std::size_t s = 0; s < common; ++s) {
    const double allowed = 100.0 * static_cast<double>(s + 1) * n * eps * largest;
    if (trace[s].x.size() != reference.xs[s].size() || !((trace[s].x - reference.xs[s]).cwiseAbs().maxCoeff() <= allowed)) {
      return s;
    }
  }
  return std::nullopt;
}

std::optional<std::string> sweep_evidence(const GaussSeidelProblem& p, const SweepHypothesis& h,
                                          const std::vector<GaussSeidelSweep>& trace, std::size_t s) {
  const std::optional<Swept> system = swept(p, h.system);
  const std::optional<Swept> asked = swept(p, SweptSystem::asked);
  const Eigen::VectorXd& previous = s == 0 ? p.x0 : trace[s - 1].x;
  const Eigen::VectorXd& yours = trace[s].x;
  if (!system || !asked || previous.size() != asked->c.size() || yours.size() != previous.size()) return std::nullopt;
  const Eigen::VectorXd hypothesis = sweep(*system, previous, h.kind);
  const Eigen::VectorXd right = sweep(*asked, previous, SweepKind::gauss_seidel);
  if (hypothesis.size() != yours.size()) return std::nullopt;
  const double size = std::max({1.0, hypothesis.cwiseAbs().maxCoeff(), previous.cwiseAbs().maxCoeff()});
  const double tolerance = 100.0 * static_cast<double>(yours.size()) * eps * size *
                           std::max(row_amplification(system->M), row_amplification(asked->M));
  const double distance = (yours - hypothesis).cwiseAbs().maxCoeff();
  const double separation = (hypothesis - right).cwiseAbs().maxCoeff();
  if (!explains(distance, separation, tolerance, tolerance)) return std::nullopt;
  return fmt::format("your sweep {} equals {} from {} to {} (a Gauss-Seidel sweep from the same x differs from it by "
                     "{}): {}",
                     s + 1, h.what, s == 0 ? std::string("x0") : fmt::format("your sweep {}'s x", s), measured(distance),
                     measured(separation), h.remedy);
}

// Whether a whole replayed run gives the student's status, sweep count, x and trace length, where
// numlab's run does not.
bool run_explains(const GaussSeidelRun& run, const GaussSeidelRun& reference, const GaussSeidelAnswer& answer) {
  if (run.status != answer.status || run.sweeps() != answer.iterations || run.xs.empty()) return false;
  const Eigen::VectorXd& last = run.xs.back();
  if (answer.x && !(relative_distance(*answer.x, last) <= 1e-6)) return false;
  if (answer.trace) {
    if (answer.trace->size() != run.xs.size()) return false;
    if (!(relative_distance(answer.trace->back().x, last) <= 1e-6)) return false;
  }
  const bool differs = run.status != reference.status || std::abs(run.sweeps() - reference.sweeps()) > 1 ||
                       (answer.trace && run.sweeps() != reference.sweeps()) ||
                       !(relative_distance(last, reference.xs.back()) <= 1e-6);
  return differs;
}

}  // namespace

GaussSeidelRun replay_gauss_seidel(const GaussSeidelProblem& p, SweptSystem system, SweepKind kind, StopRule stop) {
  GaussSeidelRun run;
  const std::optional<Swept> s = swept(p, system);
  if (!s || s->c.size() != p.x0.size()) return run;
  Eigen::VectorXd x = p.x0;
  double first = 0.0;
  run.status = "max_iterations";
  const int limit = p.max_iterations + (stop == StopRule::extra_sweep ? 1 : 0);
  for (int count = 1; count <= limit; ++count) {
    const Eigen::VectorXd old = x;
    x = sweep(*s, x, kind);
    const double update = (x - old).cwiseAbs().maxCoeff();
    if (count == 1) first = update;
    run.xs.push_back(x);
    run.updates.push_back(update);
    if (!x.allFinite()) {
      run.status = "diverged";
      return run;
    }
    const double r = residual_rule(stop) && p.b.size() == p.A.rows() && p.A.cols() == x.size() ? residual(stop, p, *s, x) : 0.0;
    if (stops(stop, x, old, update, p.tolerance, r)) {
      run.status = "converged";
      return run;
    }
    if (update > 1e8 * std::max(first, p.tolerance)) {
      run.status = "diverged";
      return run;
    }
  }
  if (stop == StopRule::limit_converged) run.status = "converged";
  return run;
}

std::optional<Diagnosis> diagnose_gauss_seidel(const GaussSeidelProblem& p, const GaussSeidelAnswer& answer) {
  const GaussSeidelRun reference = replay_gauss_seidel(p, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::stated);
  if (reference.xs.empty()) return std::nullopt;
  std::vector<Detector> detectors;
  // The reply's x is x0 itself, where numlab's sweeps move it.
  detectors.push_back({"x_never_updated", Specificity::exact, [&]() -> std::optional<std::string> {
                         if (!answer.x || answer.x->size() != p.x0.size()) return std::nullopt;
                         const double moved = relative_distance(reference.xs.back(), p.x0);
                         const double distance = relative_distance(*answer.x, p.x0);
                         if (!explains(distance, moved, 1e-15, 1e-6)) return std::nullopt;
                         return fmt::format("your x is x0 to {} after {} sweeps, where numlab's sweeps move x by {} "
                                            "(relative): assign x_i inside the sweep, and reply the updated x",
                                            measured(distance), answer.iterations, measured(moved));
                       }});
  // The first sweep that departs, against the known wrong sweeps from the student's previous x.
  std::optional<std::size_t> departing;
  if (answer.trace) departing = first_departing_sweep(reference, *answer.trace, static_cast<double>(p.x0.size()));
  if (departing) {
    for (const SweepHypothesis& h : sweep_hypotheses(p)) {
      detectors.push_back({h.cause, Specificity::exact, [&p, &answer, h, s = *departing]() {
                             return sweep_evidence(p, h, *answer.trace, s);
                           }});
    }
  }
  // Whole runs: the wrong systems and sweeps (without a trace), then the wrong stop rules. Where
  // several end as the student's run does, only those whose x is about as near the student's as the
  // nearest one's are named (two codes of one method end within rounding of each other; another
  // method that stops at the same sweep ends farther off).
  std::vector<std::pair<SweepHypothesis, GaussSeidelRun>> sweep_runs;
  std::vector<std::pair<StopHypothesis, GaussSeidelRun>> stop_runs;
  if (!answer.trace) {
    for (const SweepHypothesis& h : sweep_hypotheses(p)) {
      sweep_runs.emplace_back(h, replay_gauss_seidel(p, h.system, h.kind, StopRule::stated));
    }
  }
  if (!departing) {
    for (const StopHypothesis& h : stop_hypotheses) {
      stop_runs.emplace_back(h, replay_gauss_seidel(p, SweptSystem::asked, SweepKind::gauss_seidel, h.rule));
    }
  }
  const Eigen::VectorXd* yours = answer.x ? &*answer.x : answer.trace && !answer.trace->empty() ? &answer.trace->back().x
                                                                                                : nullptr;
  const auto distance_to = [yours](const GaussSeidelRun& run) {
    return yours == nullptr || run.xs.empty() ? 0.0 : relative_distance(*yours, run.xs.back());
  };
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [h, run] : sweep_runs) {
    if (run_explains(run, reference, answer)) nearest = std::min(nearest, distance_to(run));
  }
  for (const auto& [h, run] : stop_runs) {
    if (run_explains(run, reference, answer)) nearest = std::min(nearest, distance_to(run));
  }
  const auto named = [&](const GaussSeidelRun& run) {
    return run_explains(run, reference, answer) && distance_to(run) <= std::max(100.0 * nearest, 1e-13);
  };
  for (const auto& [h, run] : sweep_runs) {
    detectors.push_back({h.cause, Specificity::exact, [&, &h = h, &run = run]() -> std::optional<std::string> {
                           if (!named(run)) return std::nullopt;
                           return fmt::format("Gauss-Seidel with {} ends {} as you do (numlab's ends {}): {}", h.what,
                                              ending(run.status, run.sweeps()),
                                              ending(reference.status, reference.sweeps()), h.remedy);
                         }});
  }
  for (const auto& [h, run] : stop_runs) {
    detectors.push_back({h.cause, Specificity::exact, [&, &h = h, &run = run]() -> std::optional<std::string> {
                           if (!named(run)) return std::nullopt;
                           const double threshold = p.tolerance * std::max(1.0, run.xs.back().cwiseAbs().maxCoeff());
                           const std::optional<Swept> asked = swept(p, SweptSystem::asked);
                           const std::string residual_note =
                               residual_rule(h.rule) && asked
                                   ? fmt::format("the residual is {} <= tolerance = {}, ",
                                                 measured(residual(h.rule, p, *asked, run.xs.back())),
                                                 measured(p.tolerance))
                                   : std::string();
                           // Other wrong rules that end alike on this request are named too: the
                           // request cannot tell them apart (x0 below the solution: every change > 0).
                           std::string what = h.what;
                           int alike = 1;
                           for (const auto& [other, other_run] : stop_runs) {
                             if (&other == &h || !named(other_run) || other_run.status != run.status ||
                                 other_run.sweeps() != run.sweeps()) {
                               continue;
                             }
                             what += std::string(", or ") + other.what;
                             ++alike;
                           }
                           if (alike > 1) what = fmt::format("{} ({} rules that end alike on this request)", what, alike);
                           return fmt::format("{} ends {} as you do, where {}update_inf is {} and tolerance*max(1,|x|) "
                                              "= {} (numlab's ends {}): {}",
                                              what, ending(run.status, run.sweeps()), residual_note,
                                              measured(run.updates.back()), measured(threshold),
                                              ending(reference.status, reference.sweeps()), h.remedy);
                         }});
  }
  return diagnose(detectors);
}

}  // namespace numlab::exercises::detectors
