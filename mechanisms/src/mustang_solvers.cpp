#include "numlab/mechanisms/mustang_solvers.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>

#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/full_newton_pose_solver.hpp"
#include "numlab/mechanisms/gsl_pose_solver.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::mechanisms {

namespace {

// ||f||_inf of all eight equations at (theta, x).
double residual_norm_of(const MustangClosure& closure, const MustangAngles& x) {
  MustangClosure::Vector f;
  closure.residual(x, f);
  return f.lpNorm<Eigen::Infinity>();
}

// Sequential Newton: loop 1, 2, 3, 4 in turn, each a 2x2 Newton with the closed-form inverse.
class Sequential final : public MustangPoseSolver {
 public:
  explicit Sequential(const nonlinear::NewtonOptions& options) : closure_(0.0), newton_(loop_, options) {}
  PoseOutcome solve(double theta, MustangAngles& x) override {
    closure_.set_crank_angle(theta);
    PoseOutcome outcome;
    failed_loop_ = 0;
    for (int k = 0; k < MustangClosure::loops; ++k) {
      // The loop's known part reads the unknowns already solved; Newton finds its own pair.
      loop_.terms = closure_.loop(k, x);
      const auto result = newton_.solve(Eigen::Vector2d(x(2 * k), x(2 * k + 1)));
      x.segment<2>(2 * k) = result.x;
      outcome.iterations += result.iterations;
      if (result.status != Status::converged) {
        outcome.status = result.status;
        failed_loop_ = k + 1;
        break;
      }
    }
    if (failed_loop_ == 0) outcome.status = Status::converged;
    outcome.residual_norm = residual_norm_of(closure_, x);
    return outcome;
  }

 private:
  MustangClosure closure_;
  MustangLoop loop_;
  nonlinear::Newton<MustangLoop, linalg::ClosedForm2x2> newton_;
};

// The closed form, giving the same outputs (the angles) as the iterative solvers.
class Analytic final : public MustangPoseSolver {
 public:
  PoseOutcome solve(double theta, MustangAngles& x) override {
    const MustangClosedForm exact = linkage_.closed_form(theta);
    failed_loop_ = exact.failed_loop;
    if (exact.status != Status::converged) return {exact.status, 0, 0.0};
    x = MustangLinkage::angles_of(exact.joints, x);
    return {Status::converged, 0, 0.0};
  }

 private:
  MustangLinkage linkage_;
};

}  // namespace

// The same names as the Jansen leg's solvers (docs/cli.md).
const std::vector<std::string>& mustang_solver_names() { return jansen_solver_names(); }

std::unique_ptr<MustangPoseSolver> make_mustang_solver(const std::string& solver, const std::string& linear,
                                                       const nonlinear::NewtonOptions& options) {
  if (solver == "full") return make_full_newton<MustangClosure, MustangAngles>(linear, options);
  if (solver == "sequential") return std::make_unique<Sequential>(options);
  if (solver == "analytic") return std::make_unique<Analytic>();
  const auto& names = mustang_solver_names();
  if (solver.starts_with("gsl-") && std::find(names.begin(), names.end(), solver) != names.end()) {
    return std::make_unique<GslPoseSolver<MustangClosure, MustangAngles>>(solver.substr(4), options);
  }
  throw std::invalid_argument("unknown solver '" + solver + "' (expected full, sequential, analytic or gsl-<type>)");
}

MustangStart mustang_seed_start(double residual_tolerance) {
  const double theta = MustangClosure::seed_crank_deg * std::numbers::pi / 180.0;
  const MustangClosure closure(theta);
  const Eigen::Vector2d guess = MustangClosure::seed_guess().head<2>();
  MustangStart start;
  start.x = MustangClosure::seed_guess();
  MustangLoop loop;
  nonlinear::NewtonOptions plain;
  plain.residual_tolerance = residual_tolerance;
  plain.max_iterations = 100;
  nonlinear::NewtonOptions damped = plain;
  damped.damped = true;
  for (int k = 0; k < MustangClosure::loops; ++k) {
    loop.terms = closure.loop(k, start.x);
    // What plain Newton does from the seed's guess (for the record) ...
    start.loop_status[static_cast<std::size_t>(k)] = nonlinear::newton_solve(loop, guess, plain, linalg::ClosedForm2x2()).status;
    // ... and the damped solve that starts the branch.
    const auto result = nonlinear::newton_solve(loop, guess, damped, linalg::ClosedForm2x2());
    start.x.segment<2>(2 * k) = result.x;
    start.iterations[static_cast<std::size_t>(k)] = result.iterations;
    if (result.status != Status::converged && start.status == Status::converged) start.status = result.status;
  }
  return start;
}

double mustang_condition(double theta, const MustangAngles& x) {
  MustangClosure::Matrix J;
  MustangClosure(theta).jacobian(x, J);
  const Eigen::JacobiSVD<MustangClosure::Matrix> svd(J);
  const auto& sigma = svd.singularValues();
  return sigma(7) > 0.0 ? sigma(0) / sigma(7) : std::numeric_limits<double>::infinity();
}

std::array<double, 4> mustang_loop_conditions(double theta, const MustangAngles& x) {
  MustangClosure::Matrix J;
  MustangClosure(theta).jacobian(x, J);
  std::array<double, 4> conditions{};
  for (int k = 0; k < 4; ++k) {
    conditions[static_cast<std::size_t>(k)] = linalg::inverse2x2(J.block<2, 2>(2 * k, 2 * k)).condition_number;
  }
  return conditions;
}

}  // namespace numlab::mechanisms
