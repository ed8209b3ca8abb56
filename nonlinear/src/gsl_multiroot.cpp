#include "numlab/nonlinear/gsl_multiroot.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <stdexcept>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::nonlinear {

namespace {

// The system and the evaluation counts, handed to GSL's callbacks as their `params`.
struct CallbackState {
  const DynamicSystem* system;
  Eigen::VectorXd x, f;
  Eigen::MatrixXd J;
  int function_evaluations = 0;
  int jacobian_evaluations = 0;
};

using ConstGslVectorMap = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>;
using GslVectorMap = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>>;
using GslMatrixMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>, 0, Eigen::OuterStride<>>;

ConstGslVectorMap view(const gsl_vector* v) { return {v->data, static_cast<Eigen::Index>(v->size), Eigen::InnerStride<>(v->stride)}; }
GslVectorMap view(gsl_vector* v) { return {v->data, static_cast<Eigen::Index>(v->size), Eigen::InnerStride<>(v->stride)}; }

// GSL callbacks: f(x), J(x), and both. A non-finite value is reported as GSL_EBADFUNC.
int residual_callback(const gsl_vector* x, void* params, gsl_vector* f) {
  auto& state = *static_cast<CallbackState*>(params);
  state.x = view(x);
  state.system->residual(state.x, state.f);
  ++state.function_evaluations;
  view(f) = state.f;
  return linalg::all_finite(state.f) ? GSL_SUCCESS : GSL_EBADFUNC;
}

int jacobian_callback(const gsl_vector* x, void* params, gsl_matrix* J) {
  auto& state = *static_cast<CallbackState*>(params);
  state.x = view(x);
  state.system->jacobian(state.x, state.J);
  ++state.jacobian_evaluations;
  GslMatrixMap(J->data, J->size1, J->size2, Eigen::OuterStride<>(J->tda)) = state.J;
  return linalg::all_finite(state.J) ? GSL_SUCCESS : GSL_EBADFUNC;
}

// f and J in one evaluation, as GSL's fdf solvers ask for them (shared work, when the system has it).
int both_callback(const gsl_vector* x, void* params, gsl_vector* f, gsl_matrix* J) {
  auto& state = *static_cast<CallbackState*>(params);
  state.x = view(x);
  state.system->residual_and_jacobian(state.x, state.f, state.J);
  ++state.function_evaluations;
  ++state.jacobian_evaluations;
  view(f) = state.f;
  GslMatrixMap(J->data, J->size1, J->size2, Eigen::OuterStride<>(J->tda)) = state.J;
  return linalg::all_finite(state.f) && linalg::all_finite(state.J) ? GSL_SUCCESS : GSL_EBADFUNC;
}

const gsl_multiroot_fsolver_type* derivative_free_type(const std::string& name) {
  static const std::map<std::string, const gsl_multiroot_fsolver_type*> types = {
      {"hybrids", gsl_multiroot_fsolver_hybrids},
      {"hybrid", gsl_multiroot_fsolver_hybrid},
      {"dnewton", gsl_multiroot_fsolver_dnewton},
      {"broyden", gsl_multiroot_fsolver_broyden}};
  const auto found = types.find(name);
  return found == types.end() ? nullptr : found->second;
}

const gsl_multiroot_fdfsolver_type* jacobian_type(const std::string& name) {
  static const std::map<std::string, const gsl_multiroot_fdfsolver_type*> types = {
      {"hybridsj", gsl_multiroot_fdfsolver_hybridsj},
      {"hybridj", gsl_multiroot_fdfsolver_hybridj},
      {"newton", gsl_multiroot_fdfsolver_newton},
      {"gnewton", gsl_multiroot_fdfsolver_gnewton}};
  const auto found = types.find(name);
  return found == types.end() ? nullptr : found->second;
}

// GSL's error codes as numlab statuses.
Status status_for(int gsl_status) {
  switch (gsl_status) {
    case GSL_EBADFUNC: return Status::non_finite;
    case GSL_ENOPROG:
    case GSL_ENOPROGJ: return Status::no_progress;
    case GSL_ESING:
    case GSL_EDOM: return Status::singular;
    default: return Status::no_progress;
  }
}

// The two GSL solver kinds behind one interface: allocated once, then set (to start from a
// point) and iterated any number of times; read x, f, dx.
class Solver {
 public:
  virtual ~Solver() = default;
  virtual int set(gsl_vector* x0) = 0;
  virtual int iterate() = 0;
  virtual const gsl_vector* x() const = 0;
  virtual const gsl_vector* f() const = 0;
  virtual const gsl_vector* dx() const = 0;
};

class DerivativeFreeSolver final : public Solver {
 public:
  DerivativeFreeSolver(const gsl_multiroot_fsolver_type* type, CallbackState& state, std::size_t n)
      : solver_(gsl_multiroot_fsolver_alloc(type, n)), function_{&residual_callback, n, &state} {}
  ~DerivativeFreeSolver() override { gsl_multiroot_fsolver_free(solver_); }
  int set(gsl_vector* x0) override { return gsl_multiroot_fsolver_set(solver_, &function_, x0); }
  int iterate() override { return gsl_multiroot_fsolver_iterate(solver_); }
  const gsl_vector* x() const override { return solver_->x; }
  const gsl_vector* f() const override { return solver_->f; }
  const gsl_vector* dx() const override { return solver_->dx; }

 private:
  gsl_multiroot_fsolver* solver_;
  gsl_multiroot_function function_;
};

class JacobianSolver final : public Solver {
 public:
  JacobianSolver(const gsl_multiroot_fdfsolver_type* type, CallbackState& state, std::size_t n)
      : solver_(gsl_multiroot_fdfsolver_alloc(type, n)),
        function_{&residual_callback, &jacobian_callback, &both_callback, n, &state} {}
  ~JacobianSolver() override { gsl_multiroot_fdfsolver_free(solver_); }
  int set(gsl_vector* x0) override { return gsl_multiroot_fdfsolver_set(solver_, &function_, x0); }
  int iterate() override { return gsl_multiroot_fdfsolver_iterate(solver_); }
  const gsl_vector* x() const override { return solver_->x; }
  const gsl_vector* f() const override { return solver_->f; }
  const gsl_vector* dx() const override { return solver_->dx; }

 private:
  gsl_multiroot_fdfsolver* solver_;
  gsl_multiroot_function_fdf function_;
};

}  // namespace

const std::vector<std::string>& gsl_multiroot_types() {
  static const std::vector<std::string> types = {"hybrids",  "hybrid",  "dnewton", "broyden",
                                                 "hybridsj", "hybridj", "newton",  "gnewton"};
  return types;
}

// Everything a solve needs, allocated once by the constructor.
struct GslMultiroot::Workspace {
  CallbackState state;
  std::unique_ptr<Solver> solver;
  std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> start{nullptr, gsl_vector_free};
};

GslMultiroot::GslMultiroot(const DynamicSystem& system, const std::string& type)
    : workspace_(std::make_unique<Workspace>()) {
  gsl_set_error_handler_off();  // GSL's default handler aborts; numlab reports statuses instead
  const auto n = static_cast<std::size_t>(system.dimension());
  workspace_->state.system = &system;
  if (const auto* f_type = derivative_free_type(type)) {
    workspace_->solver = std::make_unique<DerivativeFreeSolver>(f_type, workspace_->state, n);
  } else if (const auto* fdf_type = jacobian_type(type)) {
    workspace_->solver = std::make_unique<JacobianSolver>(fdf_type, workspace_->state, n);
  } else {
    throw std::invalid_argument("unknown GSL multiroot type '" + type +
                                "' (expected hybrids, hybrid, dnewton, broyden, hybridsj, hybridj, newton or gnewton)");
  }
  workspace_->start.reset(gsl_vector_alloc(n));
}

GslMultiroot::~GslMultiroot() = default;

GslMultirootResult GslMultiroot::solve(const Eigen::VectorXd& x0, const NewtonOptions& options,
                                       NewtonObserver<Eigen::Dynamic>* observer) {
  CallbackState& state = workspace_->state;
  if (x0.size() != state.system->dimension()) {
    throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                std::to_string(state.system->dimension()) + " unknowns");
  }
  linalg::require_finite(x0, "starting point");
  state.function_evaluations = 0;
  state.jacobian_evaluations = 0;
  Solver* solver = workspace_->solver.get();
  view(workspace_->start.get()) = x0;
  const int set_status = solver->set(workspace_->start.get());

  GslMultirootResult result;
  // Only a trace needs the time: without an observer the clock is not read (as in numlab's Newton).
  const auto started = observer != nullptr ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  auto finish = [&](Status status) {
    result.status = status;
    result.x = view(solver->x());
    result.residual_norm = view(solver->f()).lpNorm<Eigen::Infinity>();
    result.function_evaluations = state.function_evaluations;
    result.jacobian_evaluations = state.jacobian_evaluations;
    return result;
  };

  if (set_status != GSL_SUCCESS) {
    result.gsl_message = gsl_strerror(set_status);
    return finish(status_for(set_status));
  }
  if (gsl_multiroot_test_residual(solver->f(), options.residual_tolerance) == GSL_SUCCESS) return finish(Status::converged);

  while (result.iterations < options.max_iterations) {
    ++result.iterations;
    const int status = solver->iterate();
    result.step_norm = view(solver->dx()).lpNorm<Eigen::Infinity>();
    if (observer != nullptr) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const auto f = view(solver->f());
      observer->on_iteration({result.iterations, f.lpNorm<Eigen::Infinity>(), f.norm(), result.step_norm,
                              Status::converged, NewtonRecord::no_linear_solve, 1.0, elapsed});
    }
    if (status != GSL_SUCCESS) {
      result.gsl_message = gsl_strerror(status);
      return finish(status_for(status));
    }
    if (!view(solver->x()).allFinite()) return finish(Status::non_finite);
    if (gsl_multiroot_test_residual(solver->f(), options.residual_tolerance) == GSL_SUCCESS) {
      return finish(Status::converged);
    }
    if (gsl_multiroot_test_delta(solver->dx(), solver->x(), options.step_tolerance, options.step_tolerance) ==
        GSL_SUCCESS) {
      return finish(Status::converged);
    }
  }
  return finish(Status::max_iterations);
}

GslMultirootResult gsl_multiroot_solve(const DynamicSystem& system, const Eigen::VectorXd& x0, const std::string& type,
                                       const NewtonOptions& options, NewtonObserver<Eigen::Dynamic>* observer) {
  return GslMultiroot(system, type).solve(x0, options, observer);
}

}  // namespace numlab::nonlinear
