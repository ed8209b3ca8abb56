#include "numlab/mechanisms/mustang_solvers.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"

namespace numlab::mechanisms {

namespace {

// ||f||_inf of all eight equations at (theta, x).
double residual_inf(const MustangClosure& closure, const MustangAngles& x) {
  MustangClosure::Vector f;
  closure.residual(x, f);
  return f.lpNorm<Eigen::Infinity>();
}

// Sequential Newton: loop 1, 2, 3, 4 in turn, each a 2x2 Newton with the closed-form inverse.
class Sequential final : public MustangPoseSolver {
 public:
  explicit Sequential(const nonlinear::NewtonOptions& options) : closure_(0.0), newton_(loop_, options) {}
  MustangOutcome solve(double theta, MustangAngles& x) override {
    closure_.set_crank_angle(theta);
    MustangOutcome outcome;
    for (int k = 0; k < MustangClosure::loops; ++k) {
      // The loop's known part reads the unknowns already solved; Newton finds its own pair.
      loop_.terms = closure_.loop(k, x);
      const auto result = newton_.solve(Eigen::Vector2d(x(2 * k), x(2 * k + 1)));
      x.segment<2>(2 * k) = result.x;
      outcome.iterations += result.iterations;
      if (result.status != Status::converged) {
        outcome.status = result.status;
        outcome.failed_loop = k + 1;
        break;
      }
    }
    outcome.residual_inf = residual_inf(closure_, x);
    return outcome;
  }

 private:
  MustangClosure closure_;
  MustangLoop loop_;
  nonlinear::Newton<MustangLoop, linalg::ClosedForm2x2> newton_;
};

// Full Newton on all eight equations with a compile-time linear solver.
template <typename LinearStep>
class Full final : public MustangPoseSolver {
 public:
  explicit Full(const nonlinear::NewtonOptions& options) : closure_(0.0), newton_(closure_, options) {}
  Full(const nonlinear::NewtonOptions& options, LinearStep step) : closure_(0.0), newton_(closure_, options, std::move(step)) {}
  MustangOutcome solve(double theta, MustangAngles& x) override {
    closure_.set_crank_angle(theta);
    const auto result = newton_.solve(x);
    x = result.x;
    return {result.status, result.iterations, result.residual_norm, 0};
  }

 private:
  MustangClosure closure_;
  nonlinear::Newton<MustangClosure, LinearStep> newton_;
};

class Gsl final : public MustangPoseSolver {
 public:
  Gsl(std::string type, const nonlinear::NewtonOptions& options)
      : type_(std::move(type)), options_(options), closure_(0.0), dynamic_(closure_) {}
  MustangOutcome solve(double theta, MustangAngles& x) override {
    closure_.set_crank_angle(theta);
    const auto result = nonlinear::gsl_multiroot_solve(dynamic_, Eigen::VectorXd(x), type_, options_);
    if (result.x.allFinite()) x = result.x;
    return {result.status, result.iterations, result.residual_norm, 0};
  }

 private:
  std::string type_;
  nonlinear::NewtonOptions options_;
  MustangClosure closure_;
  nonlinear::AsDynamicSystem<MustangClosure> dynamic_;
};

// The closed form, giving the same outputs (the angles) as the iterative solvers.
class Analytic final : public MustangPoseSolver {
 public:
  MustangOutcome solve(double theta, MustangAngles& x) override {
    const MustangClosedForm exact = linkage_.closed_form(theta);
    if (exact.status != Status::converged) return {exact.status, 0, 0.0, exact.failed_loop};
    x = MustangLinkage::angles_of(exact.joints, x);
    return {Status::converged, 0, 0.0, 0};
  }

 private:
  MustangLinkage linkage_;
};

std::unique_ptr<MustangPoseSolver> make_full(const std::string& linear, const nonlinear::NewtonOptions& options) {
  if (linear == "gepp") return std::make_unique<Full<linalg::GaussElimination<8>>>(options);
  if (linear == "gauss-seidel") {
    linalg::GaussSeidelOptions inner;  // far below Newton's tolerance, as for the Jansen leg
    inner.tolerance = std::min(1e-9, 1e-3 * options.residual_tolerance);
    inner.max_iterations = 100000;
    return std::make_unique<Full<linalg::GaussSeidel<8>>>(options, linalg::GaussSeidel<8>(inner));
  }
  if (linear == "gsl-lu") return std::make_unique<Full<nonlinear::GslLuStep<8>>>(options);
  if (linear == "eigen-lu") return std::make_unique<Full<linalg::EigenLu<8>>>(options);
  throw std::invalid_argument("unknown linear method '" + linear + "' for full Newton (expected gepp, gauss-seidel, "
                              "gsl-lu or eigen-lu)");
}

}  // namespace

// The same names as the Jansen leg's solvers (design/cli.md).
const std::vector<std::string>& mustang_solver_names() { return jansen_solver_names(); }

std::unique_ptr<MustangPoseSolver> make_mustang_solver(const std::string& solver, const std::string& linear,
                                                       const nonlinear::NewtonOptions& options) {
  if (solver == "full") return make_full(linear, options);
  if (solver == "sequential") return std::make_unique<Sequential>(options);
  if (solver == "analytic") return std::make_unique<Analytic>();
  const auto& names = mustang_solver_names();
  if (solver.starts_with("gsl-") && std::find(names.begin(), names.end(), solver) != names.end()) {
    return std::make_unique<Gsl>(solver.substr(4), options);
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
