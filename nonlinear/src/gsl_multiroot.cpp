#include "numlab/nonlinear/gsl_multiroot.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/stopping_tests.hpp"

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

// GSL's error codes as stop reasons (their status is status_of(reason), as for every method).
StopReason reason_for(int gsl_status) {
  switch (gsl_status) {
    case GSL_EBADFUNC: return StopReason::non_finite;
    case GSL_ESING:
    case GSL_EDOM: return StopReason::singular_jacobian;
    default: return StopReason::no_progress;  // GSL_ENOPROG, GSL_ENOPROGJ and anything else
  }
}

// The trust region of GSL's hybrid types (Powell's dogleg, MINPACK's hybrd/hybrj): its radius delta,
// in the norm ||D p||_2 of the column scaling D (D = I for hybrid and hybridj). GSL keeps it in a
// private state (multiroots/hybrid.c, hybridj.c of GSL 2.7) that both types begin with these
// fields, then differ: hybrid's state holds its finite-difference J before q, r, rdiag, diag.
// Read only after the layout has been checked (check_after_set): the state's size as GSL
// allocates it, and, right after set(), GSL's own starting values (iter 1, counters 0, delta = 100
// ||D x0||_2, or 100 when D x0 = 0); a GSL whose layout differs keeps the step test.
struct HybridStateFields {
  std::size_t iter, ncfail, ncsuc, nslow1, nslow2;
  double fnorm, delta;
};
struct HybridjLayout {  // hybridj_state_t
  HybridStateFields fields;
  gsl_matrix *q, *r;
  gsl_vector *rdiag, *diag, *qtf, *newton, *gradient, *x_trial, *f_trial, *df, *qtdf, *rdx, *w, *v;
};
struct HybridLayout {  // hybrid_state_t
  HybridStateFields fields;
  gsl_matrix *J, *q, *r;
  gsl_vector *rdiag, *diag, *qtf, *newton, *gradient, *x_trial, *f_trial, *df, *qtdf, *rdx, *w, *v;
};

class HybridState {
 public:
  // Of a solver of GSL type `name` with allocated state `state` of `size` bytes (GSL's own record of
  // it); not usable() for a type that is not hybrid or a layout that is not the one above.
  HybridState(const std::string& name, void* state, std::size_t size) : state_(state) {
    if (name == "hybridj" || name == "hybridsj") {
      jacobian_type_ = true;
      usable_ = size == sizeof(HybridjLayout);
    } else if (name == "hybrid" || name == "hybrids") {
      usable_ = size == sizeof(HybridLayout);
    }
  }
  // Right after set(x0): the layout is used only if GSL's starting values are where it says.
  void check_after_set(const gsl_vector* x0) {
    if (!usable_) return;
    const HybridStateFields& f = fields();
    const gsl_vector* d = diag();
    usable_ = f.iter == 1 && f.ncfail == 0 && f.ncsuc == 0 && f.nslow1 == 0 && f.nslow2 == 0 && d != nullptr &&
              d->size == x0->size;
    if (!usable_) return;
    const double dx0 = scaled_norm(x0);
    const double expected = dx0 > 0.0 ? 100.0 * dx0 : 100.0;  // GSL's compute_delta
    usable_ = std::abs(f.delta - expected) <= 1e-12 * expected;
  }
  bool usable() const { return usable_; }
  double radius() const { return fields().delta; }
  // ||D x||_2, in the radius' norm.
  double scaled_norm(const gsl_vector* x) const {
    const gsl_vector* d = diag();
    double sum = 0.0;
    for (std::size_t i = 0; i < x->size; ++i) {
      const double v = gsl_vector_get(d, i) * gsl_vector_get(x, i);
      sum += v * v;
    }
    return std::sqrt(sum);
  }

 private:
  const HybridStateFields& fields() const { return *static_cast<const HybridStateFields*>(state_); }
  const gsl_vector* diag() const {
    return jacobian_type_ ? static_cast<const HybridjLayout*>(state_)->diag : static_cast<const HybridLayout*>(state_)->diag;
  }
  void* state_;
  bool jacobian_type_ = false;
  bool usable_ = false;
};

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
  // The trust region of a hybrid type (HybridState), or null: every other type.
  virtual const HybridState* trust_region() const { return nullptr; }
};

class DerivativeFreeSolver final : public Solver {
 public:
  DerivativeFreeSolver(const gsl_multiroot_fsolver_type* type, CallbackState& state, std::size_t n)
      : solver_(gsl_multiroot_fsolver_alloc(type, n)), function_{&residual_callback, n, &state},
        hybrid_(type->name, solver_->state, type->size) {}
  ~DerivativeFreeSolver() override { gsl_multiroot_fsolver_free(solver_); }
  int set(gsl_vector* x0) override {
    const int status = gsl_multiroot_fsolver_set(solver_, &function_, x0);
    hybrid_.check_after_set(x0);
    return status;
  }
  int iterate() override { return gsl_multiroot_fsolver_iterate(solver_); }
  const gsl_vector* x() const override { return solver_->x; }
  const gsl_vector* f() const override { return solver_->f; }
  const gsl_vector* dx() const override { return solver_->dx; }
  const HybridState* trust_region() const override { return hybrid_.usable() ? &hybrid_ : nullptr; }

 private:
  gsl_multiroot_fsolver* solver_;
  gsl_multiroot_function function_;
  HybridState hybrid_;
};

class JacobianSolver final : public Solver {
 public:
  JacobianSolver(const gsl_multiroot_fdfsolver_type* type, CallbackState& state, std::size_t n)
      : solver_(gsl_multiroot_fdfsolver_alloc(type, n)),
        function_{&residual_callback, &jacobian_callback, &both_callback, n, &state},
        hybrid_(type->name, solver_->state, type->size) {}
  ~JacobianSolver() override { gsl_multiroot_fdfsolver_free(solver_); }
  int set(gsl_vector* x0) override {
    const int status = gsl_multiroot_fdfsolver_set(solver_, &function_, x0);
    hybrid_.check_after_set(x0);
    return status;
  }
  int iterate() override { return gsl_multiroot_fdfsolver_iterate(solver_); }
  const gsl_vector* x() const override { return solver_->x; }
  const gsl_vector* f() const override { return solver_->f; }
  const gsl_vector* dx() const override { return solver_->dx; }
  const HybridState* trust_region() const override { return hybrid_.usable() ? &hybrid_ : nullptr; }

 private:
  gsl_multiroot_fdfsolver* solver_;
  gsl_multiroot_function_fdf function_;
  HybridState hybrid_;
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
  std::chrono::steady_clock::time_point started_at;  // read only when an observer is attached
};

GslMultiroot::GslMultiroot(const DynamicSystem& system, const std::string& type, NewtonOptions options)
    : workspace_(std::make_unique<Workspace>()), options_(options) {
  gsl_set_error_handler_off();  // GSL's default handler aborts; numlab reports statuses instead
  require_tolerance(options_.residual_tolerance, "residual tolerance");
  require_tolerance(options_.step_tolerance, "step tolerance");
  if (options_.max_iterations < 1) {
    throw std::invalid_argument("iteration limit must be at least 1, got " + std::to_string(options_.max_iterations));
  }
  if (options_.damped) {
    throw std::invalid_argument("damping applies to numlab's Newton only: GSL's types choose their own steps");
  }
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
  x_.setZero(system.dimension());
}

GslMultiroot::~GslMultiroot() = default;

void GslMultiroot::start(const Eigen::VectorXd& x0) {
  CallbackState& state = workspace_->state;
  if (x0.size() != state.system->dimension()) {
    throw std::invalid_argument("starting point has " + std::to_string(x0.size()) + " entries but the system has " +
                                std::to_string(state.system->dimension()) + " unknowns");
  }
  linalg::require_finite(x0, "starting point");
  state.function_evaluations = 0;
  state.jacobian_evaluations = 0;
  counts_ = NewtonCounts{};  // status: running
  running_ = true;
  stopped_ = false;
  // Only a trace needs the time: without an observer the clock is not read (as in numlab's Newton).
  if (observer_ != nullptr) workspace_->started_at = std::chrono::steady_clock::now();

  Solver& solver = *workspace_->solver;
  view(workspace_->start.get()) = x0;
  const int set_status = solver.set(workspace_->start.get());
  x_ = view(solver.x());
  counts_.step_norm = 0.0;  // no step yet
  if (set_status != GSL_SUCCESS) {
    counts_.message = gsl_strerror(set_status);
    finish(reason_for(set_status));
  } else if (gsl_multiroot_test_residual(solver.f(), options_.residual_tolerance) == GSL_SUCCESS) {
    finish(StopReason::residual_small);
  } else if (counts_.iterations >= options_.max_iterations) {
    finish(StopReason::iteration_limit);
  }
}

bool GslMultiroot::step() {
  if (!running_) return false;
  Solver& solver = *workspace_->solver;
  ++counts_.iterations;

  // 1. One iteration of GSL's method.
  const int status = solver.iterate();
  x_ = view(solver.x());
  counts_.step_norm = view(solver.dx()).lpNorm<Eigen::Infinity>();

  // 2. GSL's stop tests, in order.
  if (status != GSL_SUCCESS) {
    counts_.message = gsl_strerror(status);
    finish(reason_for(status));
  } else if (!x_.allFinite()) {
    finish(StopReason::non_finite);
  } else if (gsl_multiroot_test_residual(solver.f(), options_.residual_tolerance) == GSL_SUCCESS) {
    finish(StopReason::residual_small);
  } else if (const HybridState* region = solver.trust_region()) {
    // A trust-region type: one rejected step may be tiny while the radius is still wide (the next
    // step, from the updated model, may well succeed). It stops as MINPACK's hybrj does, when the
    // radius itself is small: delta <= step_tolerance ||D x||_2. Not a root either.
    if (region->radius() <= options_.step_tolerance * region->scaled_norm(solver.x())) {
      finish(StopReason::radius_small);
    } else if (counts_.iterations >= options_.max_iterations) {
      finish(StopReason::iteration_limit);
    }
  } else if (gsl_multiroot_test_delta(solver.dx(), solver.x(), options_.step_tolerance, options_.step_tolerance) ==
             GSL_SUCCESS) {
    finish(StopReason::step_small);  // test_delta alone: stopped moving, not a root
  } else if (counts_.iterations >= options_.max_iterations) {
    finish(StopReason::iteration_limit);
  }
  // After the tests: the observer sees the verdict (and may end the run here).
  if (notify() == StepControl::stop && running_) {
    running_ = false;
    stopped_ = true;
  }
  return running_;
}

NewtonResult<Eigen::Dynamic> GslMultiroot::solve(const Eigen::VectorXd& x0) {
  start(x0);
  while (step()) {
  }
  return result();
}

NewtonResult<Eigen::Dynamic> GslMultiroot::result() const {
  NewtonResult<Eigen::Dynamic> result;
  static_cast<NewtonCounts&>(result) = counts_;
  result.x = x_;
  return result;
}

bool GslMultiroot::finish(StopReason reason) {
  const CallbackState& state = workspace_->state;
  counts_.status = status_of(reason);
  counts_.reason = reason;
  counts_.residual_norm = view(workspace_->solver->f()).lpNorm<Eigen::Infinity>();
  counts_.function_evaluations = state.function_evaluations;
  counts_.jacobian_evaluations = state.jacobian_evaluations;
  running_ = false;
  return false;
}

StepControl GslMultiroot::notify() {
  if (observer_ == nullptr) return StepControl::proceed;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - workspace_->started_at).count();
  const auto f = view(workspace_->solver->f());
  return observer_->on_step(*this, {counts_.iterations, f.lpNorm<Eigen::Infinity>(), f.norm(), counts_.step_norm,
                             Status::converged, NewtonRecord::no_linear_solve, 1.0, elapsed});
}

NewtonResult<Eigen::Dynamic> gsl_multiroot_solve(const DynamicSystem& system, const Eigen::VectorXd& x0,
                                                 const std::string& type, const NewtonOptions& options,
                                                 GslMultiroot::Observer* observer) {
  GslMultiroot gsl(system, type, options);
  gsl.set_observer(observer);
  return gsl.solve(x0);
}

}  // namespace numlab::nonlinear
