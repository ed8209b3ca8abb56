// Once a model, its solver and the fast path's workspace are loaded, a solve allocates nothing on
// the heap, and so no Newton iteration in it does. Counted two ways, over the whole program:
//  - malloc, calloc and realloc, wrapped at link time (-Wl,--wrap=...: every call from numlab's
//    static libraries and this file goes through the wrappers below; Eigen's heap is malloc);
//  - operator new, replaced (tests/allocations/counting_operator_new.hpp; release build only: under
//    AddressSanitizer, which owns operator new, that count is skipped; the malloc count stays).
// A positive control in each test shows that the counters see an allocation when there is one.

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> malloc_calls{0};
std::atomic<bool> counting{false};
}  // namespace

extern "C" {
void* __real_malloc(std::size_t size);
void* __real_calloc(std::size_t count, std::size_t size);
void* __real_realloc(void* memory, std::size_t size);
void* __wrap_malloc(std::size_t size) {
  if (counting) ++malloc_calls;
  return __real_malloc(size);
}
void* __wrap_calloc(std::size_t count, std::size_t size) {
  if (counting) ++malloc_calls;
  return __real_calloc(count, size);
}
void* __wrap_realloc(void* memory, std::size_t size) {
  if (counting) ++malloc_calls;
  return __real_realloc(memory, size);
}
}

#include "counting_operator_new.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include <cmath>

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

struct Allocations {
  long malloc_calls;
  long new_calls;
};

template <typename Work>
Allocations allocations_during(Work&& work) {
  malloc_calls = 0;
  numlab::testing::operator_new_calls = 0;
  counting = true;
  numlab::testing::counting_operator_new = true;
  work();
  numlab::testing::counting_operator_new = false;
  counting = false;
  return {malloc_calls.load(), numlab::testing::operator_new_calls.load()};
}

// Keeps the compiler from removing an allocation whose memory is never read.
void keep(const void* pointer) { asm volatile("" : : "g"(pointer) : "memory"); }

}  // namespace

TEST_CASE("the counters see a heap allocation when there is one", "[linkage-fast][allocations]") {
  const Allocations eigen = allocations_during([] {
    Eigen::VectorXd v(64);
    keep(v.data());
  });
  CHECK(eigen.malloc_calls >= 1);
  if (counts_operator_new) {
    const Allocations vector = allocations_during([] {
      std::vector<double> v(64);
      keep(v.data());
    });
    CHECK(vector.new_calls >= 1);
  }
}

TEST_CASE("a fast-path solve allocates nothing once the model and workspace are loaded", "[linkage-fast][allocations]") {
  for (const std::string& name : shipped_model_names()) {
    const LinkageModel model = model_file(name);
    for (const std::string kind : {"full", "sequential", "analytic"}) {
      LinkageSolverOptions options{kind, "gepp", {}};
      options.newton.residual_tolerance = 1e-10;
      bool closed = true;
      for (const LinkageBlock& block : linkage_blocks(model)) closed = closed && block.closed_form();
      if (kind == std::string("analytic") && !closed) continue;
      INFO(name << ", --solver " << kind);
      const LinkageSolver solver(model, options);
      LinkageFastSolver fast(solver);
      Eigen::VectorXd q = solver.reference();  // sized before counting
      int iterations = 0, converged = 0;
      // Half a degree at a time through 30 degrees from the reference pose, each pose predicted from
      // the last, as a sweep does (poses that do not assemble, near a limit, count too).
      const Allocations during = allocations_during([&] {
        double t = solver.reference_driver();
        for (int k = 0; k < 60; ++k) {
          const double next = t + 0.5 * deg;
          fast.predict(t, q, next);
          const LinkageFastOutcome outcome = fast.solve(next, q);
          iterations += outcome.outcome.iterations;
          converged += outcome.outcome.status == numlab::Status::converged ? 1 : 0;
          t = next;
        }
      });
      CHECK(during.malloc_calls == 0);
      CHECK(during.new_calls == 0);
      CHECK(converged > 0);
      if (kind != std::string("analytic")) CHECK(iterations > 0);  // Newton iterations were counted
    }
  }
}

TEST_CASE("the driving torque (one more linear solve per pose) allocates nothing once its solver is made",
          "[linkage-fast][allocations]") {
  // The shipped four-bar with a torque, a force and a mass: every kind of load.
  std::string text = numlab::linalg::read_text_file(model_path("four-bar"));
  text += "\n[[load]]\nlink = \"Q-B\"\ntorque = -10.0\n[[load]]\njoint = \"B\"\nmass = 2.0\n[[load]]\njoint = \"A\"\nforce = [3.0, -4.0]\n";
  const LinkageModel model(parse_linkage_description(text, "four-bar-loads.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  const LinkageSweep sweep = linkage_sweep(solver, 0.0, 350.0, 10.0);
  LinkageStaticsSolver statics(model);
  double sum = 0.0;
  int equilibria = 0;
  const Allocations during = allocations_during([&] {
    for (const LinkagePose& pose : sweep.poses) {
      const LinkageStatics& s = statics.solve(pose);
      sum += s.driver;
      equilibria += s.status == StaticsStatus::equilibrium ? 1 : 0;
    }
  });
  CHECK(during.malloc_calls == 0);
  CHECK(during.new_calls == 0);
  CHECK(equilibria == static_cast<int>(sweep.poses.size()));
  CHECK(std::isfinite(sum));
}
