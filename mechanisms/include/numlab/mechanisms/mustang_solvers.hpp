#pragma once
// Ways to find one pose of the Mustang linkage, behind one interface (docs/cli.md's names):
// full (Newton on all 8 equations, inner solver `linear`: gepp, gauss-seidel, gsl-lu, eigen-lu),
// sequential (seed 003's four 2x2 loops in order, each by Newton with the closed-form 2x2 inverse),
// analytic (the circle intersections), gsl-<type> (GSL's multiroot types on all 8 equations).

#include <memory>
#include <string>
#include <vector>

#include "numlab/mechanisms/mustang_linkage.hpp"
#include "numlab/mechanisms/pose_solver.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

// The Mustang's pose solvers work on its eight angles A ... H. After a failed solve, the loop-wise
// ones (sequential and analytic) name the loop (1 ... 4) that did not close by failed_loop().
using MustangPoseSolver = PoseSolver<MustangAngles>;

const std::vector<std::string>& mustang_solver_names();

// Throws std::invalid_argument for an unknown solver or linear method.
std::unique_ptr<MustangPoseSolver> make_mustang_solver(const std::string& solver, const std::string& linear,
                                                       const nonlinear::NewtonOptions& options);

// Seed 003's start at theta = 45 deg: the loops in order, each from [pi/18, pi/2]. Loop 4 is
// 1.85 deg from its singular (collinear-kite) pose there and plain Newton wanders from that
// guess, so every loop is solved with damping (step halved until ||f|| decreases).
struct MustangStart {
  MustangAngles x;
  Status status = Status::converged;
  std::array<int, 4> iterations{};        // per loop
  std::array<Status, 4> loop_status{};    // plain Newton from the same guess, per loop
};
MustangStart mustang_seed_start(double residual_tolerance = 1e-12);

// kappa_2 of the 8x8 Jacobian at (theta, x), and of each loop's 2x2 block (exact, closed form).
double mustang_condition(double theta, const MustangAngles& x);
std::array<double, 4> mustang_loop_conditions(double theta, const MustangAngles& x);

}  // namespace numlab::mechanisms
