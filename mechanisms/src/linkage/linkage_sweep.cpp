#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <stdexcept>

namespace numlab::mechanisms {

namespace {

constexpr double not_computed = std::numeric_limits<double>::quiet_NaN();  // a figure left out
constexpr int max_halvings = 8;          // a continuation step is halved at most this often
constexpr double crank_walk_deg = 2.0;   // the walk from the reference pose to the sweep's start
constexpr int slider_walk_steps = 50;
constexpr double crank_limit_deg = 0.01; // assembly limits to this bracket
constexpr int max_bisections = 60;

bool converged(const LinkageSolution& s) { return s.outcome.status == Status::converged; }

// The first-order predictor of continuation: q + qdot (next - at), qdot from J qdot = -Phi_t.
Eigen::VectorXd predicted(const LinkageModel& model, double at, const Eigen::VectorXd& q, double next) {
  const Eigen::VectorXd velocity = linkage_velocity(model, at, q);
  return velocity.allFinite() ? Eigen::VectorXd(q + velocity * (next - at)) : q;
}

// The pose solves of a continuation: the fast path (linkage_fast_solver.hpp) where it applies, else
// the generic solver; both predict and solve in place.
class PoseSolver {
 public:
  PoseSolver(const LinkageSolver& solver, bool fast) : solver_(solver) {
    if (fast && LinkageFastSolver::applies(solver.options())) fast_.emplace(solver);
  }
  const LinkageSolver& solver() const { return solver_; }
  LinkageFastOutcome solve(double t, Eigen::VectorXd& q) {
    if (fast_) return fast_->solve(t, q);
    LinkageSolution solution = solver_.solve(t, q);
    q = std::move(solution.q);
    return {solution.outcome, solution.failed_block};
  }
  void predict(double at, Eigen::VectorXd& q, double next) {
    if (fast_) fast_->predict(at, q, next);
    else q = predicted(solver_.model(), at, q, next);
  }

 private:
  const LinkageSolver& solver_;
  std::optional<LinkageFastSolver> fast_;
};

// From q at driver `from` to driver `to` (model units) in steps no longer than `longest`, each
// solve started from the predictor; a step that fails is halved. q becomes the last solution
// (failed or not); `trial` is scratch of q's size.
LinkageFastOutcome continue_in_place(PoseSolver& poses, double from, double to, Eigen::VectorXd& q, Eigen::VectorXd& trial,
                                     double longest, int* halvings = nullptr) {
  if (from == to) return poses.solve(to, q);  // measured, never assumed
  LinkageFastOutcome last;
  last.outcome.status = Status::converged;
  double at = from;
  double step = std::abs(to - at) <= longest ? to - at : std::copysign(longest, to - at);
  int halved = 0;
  int iterations = 0;  // over every sub-step
  while (at != to) {
    const double next = std::abs(to - at) <= std::abs(step) ? to : at + step;
    trial = q;
    poses.predict(at, trial, next);
    LinkageFastOutcome outcome = poses.solve(next, trial);
    iterations += outcome.outcome.iterations;
    if (outcome.outcome.status == Status::converged) {
      q.swap(trial);
      last = outcome;
      at = next;
      continue;
    }
    if (halved == max_halvings) {
      q.swap(trial);
      outcome.outcome.iterations = iterations;
      return outcome;
    }
    step /= 2.0;
    ++halved;
  }
  if (halvings != nullptr) *halvings = halved;
  last.outcome.iterations = iterations;
  return last;
}

// The same, as a LinkageSolution.
LinkageSolution continue_to(PoseSolver& poses, double from, double to, const Eigen::VectorXd& q, double longest,
                            int* halvings = nullptr) {
  LinkageSolution solution{q, {}, -1};
  Eigen::VectorXd trial(q.size());
  const LinkageFastOutcome outcome = continue_in_place(poses, from, to, solution.q, trial, longest, halvings);
  solution.outcome = outcome.outcome;
  solution.failed_block = outcome.failed_block;
  return solution;
}

}  // namespace

Eigen::VectorXd linkage_velocity(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  Eigen::MatrixXd J;
  Eigen::VectorXd phi_t;
  model.jacobian(q, t, J);
  model.driver_derivative(q, t, phi_t);
  return Eigen::PartialPivLU<Eigen::MatrixXd>(J).solve(-phi_t);
}

void linkage_kinematics(const LinkageModel& model, double t, const Eigen::VectorXd& q, Eigen::VectorXd& velocity,
                        Eigen::VectorXd& acceleration) {
  Eigen::MatrixXd J;
  Eigen::VectorXd phi_t, gamma;
  model.jacobian(q, t, J);
  model.driver_derivative(q, t, phi_t);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
  velocity = lu.solve(-phi_t);                 // 1. J qdot = -Phi_t
  model.acceleration_rhs(q, velocity, t, gamma);
  acceleration = lu.solve(gamma);              // 2. J qddot = gamma
}

namespace {

LinkagePose make_pose(const LinkageSolver& solver, double user, double t, LinkageSolution solution) {
  const LinkageModel& model = solver.model();
  LinkagePose pose;
  pose.driver = user;
  pose.q = std::move(solution.q);
  pose.outcome = solution.outcome;
  pose.failed_block = solution.failed_block;
  pose.condition = not_computed;
  pose.closed_form_distance = not_computed;
  pose.closed_form_bound = not_computed;
  if (converged(solution)) {
    linkage_kinematics(model, t, pose.q, pose.velocity, pose.acceleration);
    const LinkageConditioning conditioning = linkage_conditioning(model, t, pose.q);
    pose.condition = conditioning.condition;
    pose.signature = solver.signature(pose.q, t);
    pose.transmission_deg = solver.transmission_angles(pose.q);
    // The closed form, where every block has one, as an independent check of the solved pose.
    const bool all_closed = std::all_of(solver.blocks().begin(), solver.blocks().end(),
                                        [](const LinkageBlock& b) { return b.closed_form(); });
    if (all_closed) {
      const LinkageSolution closed = solver.closed_form(t, pose.q);
      if (closed.failed_block < 0) {
        Eigen::VectorXd f;
        model.residual(pose.q, t, f);
        const double n = static_cast<double>(pose.q.size());
        const double scale = pose.q.size() == 0 ? 0.0 : pose.q.lpNorm<Eigen::Infinity>();
        pose.closed_form_distance = (pose.q - closed.q).lpNorm<Eigen::Infinity>();
        pose.closed_form_bound =
            10.0 * conditioning.inverse_norm * (f.norm() + n * std::numeric_limits<double>::epsilon() * std::max(scale, 1.0));
      }
    }
  }
  return pose;
}

// The block that cannot close at t, starting from q: the closed form's, or sequential Newton's.
int failing_block(const LinkageSolver& solver, double t, const Eigen::VectorXd& q) {
  const LinkageSolution closed = solver.closed_form(t, q);
  if (closed.failed_block >= 0 && solver.blocks()[static_cast<std::size_t>(closed.failed_block)].closed_form()) {
    return closed.failed_block;
  }
  LinkageSolverOptions options = solver.options();
  options.solver = "sequential";
  // The reference pose is solved again here; cheap next to a bisection.
  const LinkageSolver sequential(solver.model(), options);
  return sequential.solve(t, q).failed_block;
}

// Bisection between a driver value that assembles (good, with its q) and one that does not.
LinkageLimit bisect_limit(PoseSolver& poses, double good, Eigen::VectorXd q, double bad, bool upper) {
  const LinkageSolver& solver = poses.solver();
  const LinkageModel& model = solver.model();
  const double target = model.crank_driven() ? crank_limit_deg * std::acos(-1.0) / 180.0 : 1e-4 * std::abs(bad - good);
  for (int i = 0; i < max_bisections && std::abs(bad - good) > target; ++i) {
    const double middle = 0.5 * (good + bad);
    LinkageSolution trial = continue_to(poses, good, middle, q, std::abs(middle - good));
    if (converged(trial)) {
      good = middle;
      q = std::move(trial.q);
    } else {
      bad = middle;
    }
  }
  LinkageLimit limit;
  limit.driver = model.driver_to_user(good);
  limit.bracket = std::abs(model.driver_to_user(bad) - model.driver_to_user(good));
  limit.upper = upper;
  limit.block = failing_block(solver, bad, q);
  const auto angles = solver.transmission_angles(q);
  limit.transmission_deg = limit.block >= 0 ? angles[static_cast<std::size_t>(limit.block)] : not_computed;
  return limit;
}

}  // namespace

// Where, between t0 (pose q0) and t1, dyad block b's two solutions meet (its margin reaches zero
// without going below: a change point), or NaN. The margin along the way comes from the closed
// form continued from q0; its smallest value is found by golden-section search.
double change_point(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0, double t1) {
  if (!solver.blocks()[b].dyad()) return std::numeric_limits<double>::quiet_NaN();
  const auto margin_at = [&](double t) {
    // The margin reads only the dyad's centres, which the blocks before it placed: it is defined even
    // where rounding makes this dyad itself fail at the meeting point.
    const LinkageSolution closed = solver.closed_form(t, predicted(solver.model(), t0, q0, t));
    const bool earlier_failed = closed.failed_block >= 0 && closed.failed_block < static_cast<int>(b);
    return earlier_failed ? -1.0 : solver.dyad_margins(closed.q)[b];
  };
  constexpr double golden = 0.6180339887498949;
  double a = t0, c = t1;
  for (int i = 0; i < 80 && std::abs(c - a) > 1e-12 * (1.0 + std::abs(t0)); ++i) {
    const double x1 = c - golden * (c - a), x2 = a + golden * (c - a);
    if (margin_at(x1) < margin_at(x2)) c = x2;
    else a = x1;
  }
  const double meet = 0.5 * (a + c);
  const double margin = margin_at(meet);
  const double scale = std::max(1.0, q0.size() == 0 ? 0.0 : q0.lpNorm<Eigen::Infinity>());
  // Zero to rounding (a little below zero is rounding too), and no further below: below is a limit.
  return margin >= -1e-12 * scale && margin <= 1e-6 * scale ? meet : std::numeric_limits<double>::quiet_NaN();
}

LinkageSweep linkage_sweep(const LinkageSolver& solver, double start, double stop, double step,
                           const LinkagePoseObserver& observer) {
  if (!std::isfinite(start) || !std::isfinite(stop) || !std::isfinite(step) || step == 0.0 ||
      (stop - start) * step < 0.0) {
    throw std::invalid_argument("the sweep's step must be finite, nonzero and point from start to stop");
  }
  const LinkageModel& model = solver.model();
  const std::size_t count = static_cast<std::size_t>(std::floor((stop - start) / step + 1e-9)) + 1;
  LinkageSweep sweep;
  // The fast path solves the poses, unless an observer traces them: --trace and --step follow the
  // generic solver (the same poses, checked by tests/linkage_fast/).
  PoseSolver poses(solver, !observer);
  // 1. Walk from the reference pose to the start: the shorter way round for a crank.
  const double reference = solver.reference_driver();
  double t_start = model.driver_from_user(start);
  double walk_to = t_start;
  if (model.crank_driven()) walk_to = reference + std::remainder(t_start - reference, 2.0 * std::acos(-1.0));
  // A slider's sub-steps: a 50th of the walk, but never shorter than the sweep's own step (a sweep
  // that starts at the reference has no walk; sub-steps of 1e-12 would never reach its next pose).
  const double longest = model.crank_driven()
                             ? model.driver_from_user(crank_walk_deg)
                             : std::max(std::abs(walk_to - reference) / slider_walk_steps,
                                        std::abs(model.driver_from_user(start + step) - t_start));
  LinkageSolution at = continue_to(poses, reference, walk_to, solver.reference(), longest);
  Eigen::VectorXd last_good = converged(at) ? at.q : solver.reference();
  double last_good_t = converged(at) ? t_start : reference;
  bool have_good = converged(at);
  std::vector<int> last_signature = solver.reference_signature();
  double shortest = std::numeric_limits<double>::infinity();
  for (const Constraint& c : model.constraints()) {
    if (c.kind == ConstraintKind::distance || c.kind == ConstraintKind::crank) shortest = std::min(shortest, c.length);
  }
  bool have_signature = true;
  // 2. Each pose from the one before; a failed pose is retried from the last good one by halving.
  for (std::size_t k = 0; k < count; ++k) {
    const double user = start + static_cast<double>(k) * step;
    const double t = model.driver_from_user(user);
    int halvings = 0;
    // Sub-steps no longer than the walk's, each from the predictor: a coarse sweep still follows
    // its branch through a change point between two of its poses.
    LinkageSolution solution = k == 0 && have_good ? at : continue_to(poses, last_good_t, t, last_good, longest, &halvings);
    LinkagePose pose = make_pose(solver, user, t, std::move(solution));
    pose.step_halvings = halvings;
    const bool ok = pose.outcome.status == Status::converged;
    // 3. A change between assembling and not is a limit, bracketed and named.
    if (k > 0) {
      const LinkagePose& before = sweep.poses.back();
      const bool was_ok = before.outcome.status == Status::converged;
      if (was_ok && !ok) sweep.limits.push_back(bisect_limit(poses, last_good_t, last_good, t, true));
      if (!was_ok && ok) {
        LinkageLimit limit = bisect_limit(poses, t, pose.q, model.driver_from_user(before.driver), false);
        sweep.limits.push_back(limit);
      }
    }
    // The rule of closed_form_bound.hpp: within the bound, and the bound below half the shortest
    // length (beyond it the residual justifies nothing: another branch is about a link away).
    if (ok && !std::isnan(pose.closed_form_distance) &&
        !(pose.closed_form_distance <= pose.closed_form_bound && pose.closed_form_bound < 0.5 * shortest)) {
      sweep.closed_form_verified = false;
    }
    if (ok) {
      // 4. The branch: a block whose signature changes from the last assembled pose either passes a
      // change point (a dyad whose two solutions meet between the poses, as a kite does when it
      // lines up: the motion goes on smoothly on the other side) or has jumped to another branch.
      if (have_signature) {
        for (std::size_t b = 0; b < pose.signature.size(); ++b) {
          if (pose.signature[b] == last_signature[b]) continue;
          const bool first = sweep.poses.empty();  // compared with the reference pose, across the walk
          const double meet = first ? change_point(solver, b, reference, solver.reference(), t)
                                    : change_point(solver, b, last_good_t, last_good, t);
          const std::string what = describe_block(model, solver.blocks()[b]);
          if (std::isfinite(meet)) {
            sweep.change_points.push_back(fmt::format("block {} ({}) passes a change point at {:.2f}: its two solutions "
                                                      "meet there, and it goes on smoothly on the other side",
                                                      b + 1, what, model.driver_to_user(meet)));
          } else {
            sweep.branch_kept = false;
            if (sweep.flips.size() < 20) {
              sweep.flips.push_back(fmt::format("block {} ({}) jumps to the other branch between {:g} and {:g}", b + 1,
                                                what, model.driver_to_user(last_good_t), user));
            }
          }
        }
      }
      last_signature = pose.signature;
      have_signature = true;
      pose.branch_kept = sweep.branch_kept;
      last_good = pose.q;
      last_good_t = t;
      have_good = true;
    } else if (sweep.status == Status::converged) {
      sweep.status = pose.outcome.status;
    }
    sweep.poses.push_back(std::move(pose));
    if (observer) observer(sweep.poses.back());
  }
  return sweep;
}

namespace {

// The next of equally spaced poses from the last m <= 5 of the `done` columns of poses (the
// polynomial of degree m - 1 through them): sum over k = 1..m of (-1)^(k+1) C(m, k) poses(done - k).
void extrapolate(const Eigen::MatrixXd& poses, Eigen::Index done, Eigen::VectorXd& next) {
  const Eigen::Index m = std::min<Eigen::Index>(done, 5);
  next.setZero();
  double binomial = 1.0;  // C(m, k), from C(m, 0)
  for (Eigen::Index k = 1; k <= m; ++k) {
    binomial = binomial * static_cast<double>(m - k + 1) / static_cast<double>(k);
    next += (k % 2 == 1 ? binomial : -binomial) * poses.col(done - k);
  }
}

}  // namespace

LinkageCycle solve_linkage_cycle(const LinkageSolver& solver, double start, double stop, double step) {
  const LinkageModel& model = solver.model();
  const std::size_t count = static_cast<std::size_t>(std::floor((stop - start) / step + 1e-9)) + 1;
  LinkageCycle cycle;
  cycle.q.resize(solver.model().unknown_count(), static_cast<Eigen::Index>(count));
  PoseSolver poses(solver, true);
  const double reference = solver.reference_driver();
  double at = model.driver_from_user(start);
  const double walk_to = model.crank_driven() ? reference + std::remainder(at - reference, 2.0 * std::acos(-1.0)) : at;
  const double longest = model.crank_driven() ? model.driver_from_user(crank_walk_deg)
                                              : std::max(std::abs(walk_to - reference) / slider_walk_steps, 1e-12);
  Eigen::VectorXd q = solver.reference(), trial(q.size());
  LinkageFastOutcome pose = continue_in_place(poses, reference, walk_to, q, trial, longest);
  for (std::size_t k = 0; k < count; ++k) {
    const double t = model.driver_from_user(start + static_cast<double>(k) * step);
    if (k > 0) {
      // The prediction of `numlab bench jansen`'s hand-coded sweeps: the polynomial through the
      // last poses (up to five), extrapolated; if its solve fails, continuation from the last pose.
      extrapolate(cycle.q, static_cast<Eigen::Index>(k), trial);
      pose = poses.solve(t, trial);
      if (pose.outcome.status == Status::converged) q.swap(trial);
      else pose = continue_in_place(poses, at, t, q, trial, std::abs(t - at));
    }
    at = t;
    cycle.iterations += pose.outcome.iterations;
    if (pose.outcome.status != Status::converged && cycle.status == Status::converged) cycle.status = pose.outcome.status;
    cycle.q.col(static_cast<Eigen::Index>(k)) = q;
  }
  return cycle;
}

DerivativeCheck check_derivatives(const LinkageSolver& solver, double t, const Eigen::VectorXd& q_near) {
  const LinkageModel& model = solver.model();
  DerivativeCheck check;
  // Positions at t + k h, solved to rounding level by full Newton from the pose: the pose itself too,
  // since a sweep's pose is only as exact as its tolerance.
  nonlinear::NewtonOptions newton = solver.options().newton;
  const double scale = std::max(1.0, q_near.size() == 0 ? 0.0 : q_near.lpNorm<Eigen::Infinity>());
  newton.residual_tolerance = 64.0 * std::numeric_limits<double>::epsilon() * scale;
  newton.max_iterations = 50;
  const auto solve_at = [&](double s) -> std::optional<Eigen::VectorXd> {
    const LinkageSystem system(model, s);
    auto result = nonlinear::newton_solve(system, q_near, newton);
    if (result.status != Status::converged) return std::nullopt;
    return result.x;
  };
  const auto q = solve_at(t);
  if (!q) {
    check.solved = false;
    return check;
  }
  Eigen::VectorXd velocity, acceleration;
  linkage_kinematics(model, t, *q, velocity, acceleration);
  check.velocity_scale = velocity.size() == 0 ? 0.0 : velocity.lpNorm<Eigen::Infinity>();
  check.acceleration_scale = acceleration.size() == 0 ? 0.0 : acceleration.lpNorm<Eigen::Infinity>();
  // Central difference for the velocity, h ~ cbrt(eps); the 7-point stencil for the acceleration.
  const double h1 = 1e-5, h2 = 1e-2;
  const auto p1 = solve_at(t + h1), m1 = solve_at(t - h1);
  std::array<std::optional<Eigen::VectorXd>, 7> s;
  for (int k = -3; k <= 3; ++k) s[static_cast<std::size_t>(k + 3)] = k == 0 ? q : solve_at(t + k * h2);
  for (const auto& p : s) check.solved = check.solved && p.has_value();
  check.solved = check.solved && p1 && m1;
  if (!check.solved) return check;
  const Eigen::VectorXd fd_velocity = (*p1 - *m1) / (2.0 * h1);
  const Eigen::VectorXd fd_acceleration =
      (2.0 * (*s[0] + *s[6]) - 27.0 * (*s[1] + *s[5]) + 270.0 * (*s[2] + *s[4]) - 490.0 * *s[3]) / (180.0 * h2 * h2);
  check.velocity_difference = (fd_velocity - velocity).lpNorm<Eigen::Infinity>();
  check.acceleration_difference = (fd_acceleration - acceleration).lpNorm<Eigen::Infinity>();
  return check;
}

}  // namespace numlab::mechanisms
