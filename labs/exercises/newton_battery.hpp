#pragma once
// The checks shared by the linkage Newton exercises (jansen-newton, mustang-newton), written once
// for any closure. A Linkage describes the exercise:
//   using Closure = ...;                       // numlab's closure (set to the input angle)
//   static constexpr const char* input;        // "crank_angle"
//   static constexpr const char* start;        // "theta0" / "guess"
//   static constexpr const char* answer;       // "theta" / "angles"
//   static std::string angle_name(int k);      // "theta3" / "C"
//   static double links_sum();                 // L, the scale of f
//   static std::string where(double angle);    // "crank 130 deg"
//   using Lengths = ...;                       // the closure's lengths: Closure(angle, Lengths)
// and may have
//   static std::vector<SlippedClosure> constant_angle_slips(const Lengths&);  // a constant angle typed in degrees

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "exercises/detectors/mechanism_newton.hpp"
#include "exercises/exercise.hpp"
#include "exercises/linkage_checks.hpp"
#include "exercises/newton_replies.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/variant_lengths.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"

namespace numlab::exercises {

template <typename Closure, typename Lengths>
struct NewtonRequest {
  double angle;  // the input angle, radians
  typename Closure::Vector start;
  double tolerance = 1e-10;
  int max_iterations = 20;
  Lengths lengths{};  // the closure's link lengths: the seed's, or a variant's
  LinkLengths named{};  // a variant's, as the request's "lengths" field; empty without a variant (no field)
};

template <typename Linkage>
class NewtonBattery {
 public:
  using Closure = typename Linkage::Closure;
  using Vector = typename Closure::Vector;
  using Request = NewtonRequest<Closure, typename Linkage::Lengths>;
  static constexpr int n = Closure::size;
  static constexpr double eps = std::numeric_limits<double>::epsilon();

  // What re-evaluating f at a pose adds by rounding: 1e3 eps times the links' sum.
  static double rounding() { return 1e3 * eps * Linkage::links_sum(); }

  static nlohmann::json to_request(const Request& request) {
    nlohmann::json json = {{Linkage::input, request.angle},
                           {Linkage::start, to_json(Eigen::VectorXd(request.start))},
                           {"tolerance", request.tolerance},
                           {"max_iterations", request.max_iterations}};
    if (!request.named.empty()) json["lengths"] = lengths_json(request.named);
    return json;
  }

  // numlab's closure of the request: its angle and its lengths.
  static Closure closure_for(const Request& request) { return Closure(request.angle, request.lengths); }

  struct Answer {
    Vector x;
    NewtonReply reply;
    nlohmann::json raw;
  };

  static Answer ask(Session& session, const Request& request) {
    Answer answer;
    answer.raw = session.ask(to_request(request));
    answer.x = Vector(vector_field(answer.raw, Linkage::answer, n));
    answer.reply.status = string_field(answer.raw, "status");
    answer.reply.iterations = integer_field(answer.raw, "iterations");
    typename Closure::Vector f;
    closure_for(request).residual(answer.x, f);
    answer.reply.residual_inf = f.template lpNorm<Eigen::Infinity>();
    return answer;
  }

  // The seed's own start, if the closure has one (restart_from_seed_guess tests it).
  static Eigen::VectorXd seed_start() {
    if constexpr (requires { Closure::seed_guess(); }) {
      return Closure::seed_guess();
    } else if constexpr (requires { Closure::seed_estimates(); }) {
      return Closure::seed_estimates();
    } else {
      return {};
    }
  }

  // numlab's Newton from the request's start: its trace, what a correct trace may differ from it
  // by, and its iteration count where the task's stop rule decides it.
  struct Reference {
    std::vector<TraceRow> rows;
    double relative = 0.0;    // two correct Newton codes agree to rounding amplified by kappa at each step
    double step_floor = 0.0;  // ||J^-1|| times what re-evaluating f adds
    double start_residual = 0.0;
    std::optional<long long> decided;
  };

  static Reference reference_for(const Request& request) {
    const Closure closure = closure_for(request);
    typename Closure::Vector f;
    typename Closure::Matrix J;
    closure.residual_and_jacobian(request.start, f, J);
    nonlinear::NewtonResult<n> result;
    Reference reference;
    reference.rows = newton_trace(closure, request.start, options_for(request), &result);
    reference.relative = std::max(1e-6, 1e3 * kappa_inf(J) * eps);
    reference.step_floor = inverse_inf_norm(J) * rounding();
    reference.start_residual = f.template lpNorm<Eigen::Infinity>();
    // Residuals of two correct codes differ by rounding in f's sum (100 eps L) beyond `relative`.
    reference.decided = decided_iterations(reference.rows, reference.start_residual, request.tolerance,
                                           request.max_iterations, result.status == Status::converged,
                                           reference.relative, rounding() / 10.0);
    return reference;
  }

  // The closure of the request's lengths with a constant angle typed in degrees and used as radians,
  // when the linkage has one (Linkage::constant_angle_slips(lengths)).
  static std::vector<SlippedClosure> constant_angle_slips(const Request& request) {
    if constexpr (requires { Linkage::constant_angle_slips(request.lengths); }) {
      return Linkage::constant_angle_slips(request.lengths);
    } else {
      return {};
    }
  }

  // numlab's Newton converges from the request's start (to `exact` when given, modulo whole turns).
  static bool newton_converges(const Request& request, const Vector* exact) {
    nonlinear::NewtonResult<n> result;
    newton_trace(closure_for(request), request.start, options_for(request), &result);
    if (result.status != Status::converged) return false;
    int worst = 0;
    return exact == nullptr || worst_angle_error(Eigen::VectorXd(result.x), Eigen::VectorXd(*exact), worst) < 1e-6;
  }
  // What a variant's lengths must allow: numlab's Newton converges from the start of each of
  // `to_exact` to its pose in `exact`, and from each start of `anywhere`.
  static bool newton_converges(const std::vector<Request>& to_exact, const std::vector<Vector>& exact,
                               const std::vector<Request>& anywhere) {
    for (std::size_t r = 0; r < to_exact.size(); ++r) {
      if (!newton_converges(to_exact[r], &exact[r])) return false;
    }
    for (const Request& request : anywhere) {
      if (!newton_converges(request, nullptr)) return false;
    }
    return true;
  }

  // The most specific cause the reply's numbers show (detectors/mechanism_newton.hpp), or nothing.
  static std::optional<Diagnosis> diagnosis(const Request& request, const Answer& answer,
                                            const std::optional<Vector>& exact = std::nullopt) {
    NewtonEvidence evidence;
    evidence.driver = request.angle;
    evidence.start = request.start;
    evidence.tolerance = request.tolerance;
    evidence.max_iterations = request.max_iterations;
    evidence.x = answer.x;
    evidence.status = answer.reply.status;
    evidence.iterations = answer.reply.iterations;
    try {
      evidence.trace = read_trace(answer.raw);
    } catch (const ReplyError&) {
      // a malformed trace is evidence of nothing: the detectors that need one stay silent
    }
    evidence.evaluate = evaluator_of<Closure>(request.lengths);
    evidence.seed_start = seed_start();
    if (exact) evidence.exact = Eigen::VectorXd(*exact);
    evidence.rounding = rounding();
    evidence.links_sum = Linkage::links_sum();
    evidence.angle_name = [](int k) { return Linkage::angle_name(k); };
    evidence.decided_iterations = reference_for(request).decided;
    evidence.constant_angle_slips = constant_angle_slips(request);
    return more_specific(diagnose({{"wrong_link", Specificity::exact, [&] { return seed_lengths_used(request, evidence); }}}),
                         diagnose_newton(evidence));
  }

  // Under a variant: the reply is Newton's on the closure with the seed's lengths (the task's
  // constants) where the request's belong: its angles solve that closure, or its trace's first row
  // is that Newton's.
  static std::optional<std::string> seed_lengths_used(const Request& request, const NewtonEvidence& evidence) {
    if (request.named.empty()) return std::nullopt;
    const ClosureEvaluator seed = evaluator_of<Closure>();
    const double near_root = 10.0 * request.tolerance + rounding();
    const double seed_residual = seed(request.angle, evidence.x).f.template lpNorm<Eigen::Infinity>();
    const double own_residual = evidence.evaluate(request.angle, evidence.x).f.template lpNorm<Eigen::Infinity>();
    bool fits = seed_residual <= near_root && own_residual > 100.0 * near_root;
    if (!fits && evidence.trace && !evidence.trace->empty()) {
      const NewtonLoop plain;
      const auto seed_rows = simulate_newton(seed, request.angle, request.start, request.tolerance, 1, plain);
      const auto own_rows = simulate_newton(evidence.evaluate, request.angle, request.start, request.tolerance, 1, plain);
      auto close = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)); };
      const TraceRow& first = evidence.trace->front();
      fits = !seed_rows.empty() && !own_rows.empty() && close(first.residual_inf, seed_rows[0].residual_inf) &&
             close(first.step_inf, seed_rows[0].step_inf) && !close(first.residual_inf, own_rows[0].residual_inf);
    }
    if (!fits) return std::nullopt;
    return fmt::format("your Newton solves the closure with the seed's lengths (TASK.md's constants), not your "
                       "variant's: {} (||f(your angles)||_inf is {} with the seed's lengths, {} with the request's); read "
                       "them from the request's \"lengths\" ({})",
                       seed_residual <= near_root ? "your angles are its root" : "your first trace row is its Newton's",
                       sci(seed_residual), sci(own_residual), lengths_text(request.named));
  }

  static nonlinear::NewtonOptions options_for(const Request& request) {
    nonlinear::NewtonOptions options;
    options.residual_tolerance = request.tolerance;
    options.max_iterations = request.max_iterations;
    options.step_tolerance = 1e-15;
    return options;
  }

  // numlab's Newton and GSL's hybridsj on the first request, per request.
  static std::vector<ReferenceTime> reference_times(const Request& request) {
    const Closure closure = closure_for(request);
    const auto options = options_for(request);
    const double numlab_seconds = median_seconds([&] { nonlinear::Newton<Closure>(closure, options).solve(request.start); });
    const nonlinear::AsDynamicSystem<Closure> dynamic(closure);
    const double gsl_seconds =
        median_seconds([&] { nonlinear::gsl_multiroot_solve(dynamic, Eigen::VectorXd(request.start), "hybridsj", options); });
    return {{"numlab Newton (GEPP)", numlab_seconds}, {"GSL multiroot hybridsj", gsl_seconds}};
  }

  // Task: each request converges, to the exact pose within what its residual and conditioning allow.
  static Verdict converges_to(Session& session, const std::vector<Request>& requests, const std::vector<Vector>& exact) {
    for (std::size_t r = 0; r < requests.size(); ++r) {
      const Request& request = requests[r];
      const Answer answer = ask(session, request);
      session.expect({Linkage::where(request.angle),
                      {{Linkage::answer, to_json(Eigen::VectorXd(exact[r]))}, {"status", "converged"}},
                      "status \"converged\" and the angles of the closed form above, to what the tolerance and "
                      "kappa(J) allow (angles modulo 2 pi)"});
      const std::string where = Linkage::where(request.angle);
      const Closure closure = closure_for(request);
      typename Closure::Vector f;
      typename Closure::Matrix J;
      closure.residual_and_jacobian(exact[r], f, J);
      const double inverse_norm = inverse_inf_norm(J);
      if (answer.reply.status != "converged") {
        nonlinear::NewtonResult<n> reference;
        newton_trace(closure, request.start, options_for(request), &reference);
        return Verdict::fail(fmt::format("{}: status \"{}\" after {} iterations; numlab's Newton from the same start "
                                         "converges in {} (tolerance {}, kappa_inf(J) = {} at the pose)",
                                         where, answer.reply.status, answer.reply.iterations, reference.iterations,
                                         sci(request.tolerance), sci(kappa_inf(J))),
                             diagnosis(request, answer, exact[r]), "check the Newton step: J dx = -f, then x <- x + dx; and J entry by entry");
      }
      // First order: |x - x*| <= ||J^-1|| ||f(x)||; f is at most tolerance, plus rounding.
      const double allowed = 2.0 * inverse_norm * (request.tolerance + rounding());
      int worst = 0;
      const double error = worst_angle_error(Eigen::VectorXd(answer.x), Eigen::VectorXd(exact[r]), worst);
      if (error > allowed) {
        return Verdict::fail(
            fmt::format("{}: {} differs from the closed form by {} rad, allowed {} (2 ||J^-1||_inf (tolerance + 1e3 eps "
                        "L), kappa_inf(J) = {}); ||f||_inf at your angles (numlab's f) = {}",
                        where, Linkage::angle_name(worst), sci(error), sci(allowed), sci(kappa_inf(J)),
                        sci(answer.reply.residual_inf)),
            diagnosis(request, answer, exact[r]), error > 0.1 ? "a root of another branch (assembly mode), or a wrong f: start from the given angles and "
                          "check f against the task's equations"
                        : "the residual test passed on a wrong f: compare f with the task's equations (lengths, "
                          "and which angles are measured from -x)");
      }
      if (auto dishonest = dishonest_reply(answer.reply, request.tolerance, request.max_iterations, rounding(), where)) {
        dishonest->diagnosis = diagnosis(request, answer, exact[r]);
        return *dishonest;
      }
    }
    return Verdict::pass(reference_times(requests.front()));
  }

  // Task: no reply claims more than it shows.
  static Verdict honest(Session& session, const std::vector<Request>& requests) {
    for (const Request& request : requests) {
      const Answer answer = ask(session, request);
      if (auto dishonest = dishonest_reply(answer.reply, request.tolerance, request.max_iterations, rounding(),
                                           Linkage::where(request.angle))) {
        dishonest->diagnosis = diagnosis(request, answer);
        return *dishonest;
      }
    }
    return Verdict::pass(reference_times(requests.front()));
  }

  // The trace's length and `iterations` against numlab's count, where the stop rule decides it.
  static std::optional<Verdict> count_mismatch(const Request& request, const Answer& answer,
                                               const std::vector<TraceRow>& trace, const Reference& reference) {
    if (!reference.decided) return std::nullopt;
    const long long count = *reference.decided, rows = static_cast<long long>(trace.size());
    if (rows == count && answer.reply.iterations == count) return std::nullopt;
    const std::string ending =
        count == 0 ? fmt::format("the start already passes (||f(start)||_inf = {})", sci(reference.start_residual))
        : count == request.max_iterations && reference.rows.back().residual_inf > request.tolerance
            ? fmt::format("it stops at max_iterations = {} (residual_inf {} after iteration {})", count,
                          sci(reference.rows.back().residual_inf), count)
            : fmt::format("residual_inf {} after iteration {} passes the test{}", sci(reference.rows.back().residual_inf),
                          count,
                          count > 1 ? fmt::format(", {} after iteration {} did not", sci(reference.rows[reference.rows.size() - 2].residual_inf), count - 1)
                                    : fmt::format(", {} at the start did not", sci(reference.start_residual)));
    std::optional<Verdict> verdict = Verdict::fail(
        fmt::format("{}: your trace has {} rows and iterations = {}; numlab's Newton from the same start takes {}: {}. "
                    "The task's stop rule (test max |f_i| <= tolerance {} at the current x before each step, count "
                    "each step) decides the count here: every residual is more than a factor 2 from the tolerance",
                    Linkage::where(request.angle), rows, answer.reply.iterations, count, ending, sci(request.tolerance)),
        diagnosis(request, answer),
        "test the residual at the current x before each step and stop as soon as it passes; one trace row and one "
        "count per step taken");
    return verdict;
  }

  // The student's trace beside numlab's for trace.html (trace_comparison.hpp), parting at `parting`.
  static TraceComparison side_by_side(const Request& request, const std::vector<TraceRow>& trace,
                                      const Reference& reference, std::size_t parting) {
    std::vector<double> your_residuals, your_steps, residuals, steps;
    for (const TraceRow& row : trace) {
      your_residuals.push_back(row.residual_inf);
      your_steps.push_back(row.step_inf);
    }
    for (const TraceRow& row : reference.rows) {
      residuals.push_back(row.residual_inf);
      steps.push_back(row.step_inf);
    }
    return newton_comparison(Linkage::where(request.angle), your_residuals, your_steps, residuals, steps, parting,
                             {reference.relative, rounding(), reference.step_floor, request.tolerance});
  }

  // Task: the trace follows numlab's Newton from the same start.
  static Verdict trace_matches(Session& session, const std::vector<Request>& requests) {
    for (const Request& request : requests) {
      const Answer answer = ask(session, request);
      const auto trace = read_trace(answer.raw);
      const std::string where = Linkage::where(request.angle);
      if (!trace) return Verdict::fail(fmt::format("{}: the reply has no \"trace\" (this task asks for one)", where));
      const Reference reference = reference_for(request);
      if (auto departure = first_departure(*trace, reference.rows, reference.relative, rounding(), reference.step_floor,
                                           reference.start_residual)) {
        Verdict verdict = Verdict::fail(fmt::format("{} (your status \"{}\" after {} iterations), {}", where,
                                                    answer.reply.status, answer.reply.iterations, departure->message),
                                        diagnosis(request, answer), departure->hint);
        verdict.trace = side_by_side(request, *trace, reference, departure->iteration);
        return verdict;
      }
      if (auto miscount = count_mismatch(request, answer, *trace, reference)) {
        // the traces part where one of them ends (when only `iterations` differs, no step parts)
        if (trace->size() != reference.rows.size()) {
          miscount->trace = side_by_side(request, *trace, reference, std::min(trace->size(), reference.rows.size()));
        }
        return *miscount;
      }
    }
    return Verdict::pass(reference_times(requests.front()));
  }
};

}  // namespace numlab::exercises
