#pragma once
// Internal to the sweep (linkage_sweep.cpp): where a dyad's two solutions meet, the words for its
// sides, and the other solution of a dyad (for --at-crossing switch).

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::mechanisms::detail {

// Where, between t0 (pose q0) and t1, dyad block b's two solutions meet (its margin reaches zero
// without going below), or NaN. The margin along the way comes from the closed form continued from
// q0; its smallest value is found by golden-section search. A meeting point at t0 itself counts only
// when at_start (the pose at t0 lies on it; else it belongs to the interval before).
double change_point(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0, double t1,
                    bool at_start = true);

// The order of the margin's contact with zero at `meet`, from its values at meet + d and meet + d/2:
// log2 of their ratio. 2 where two branches cross (the margin grows like the square of the distance),
// 4 and more where they touch without crossing; NaN where a margin is not positive.
double contact_order(const LinkageSolver& solver, std::size_t b, double t0, const Eigen::VectorXd& q0, double meet, double d);

// Whether dyad block b's side is defined at q: its two solutions are apart by more than rounding.
// Always true for other blocks.
bool side_defined(const LinkageSolver& solver, std::size_t b, const Eigen::VectorXd& q);
// The same with the block's margin at q (LinkageSolver::dyad_margins) already at hand: a sweep over
// every block reads the margins once, not once per block.
bool side_defined_at(const LinkageSolver& solver, std::size_t b, const Eigen::VectorXd& q, double margin);

// "left" / "right" of the line between a circle-circle dyad's centres; "ahead" / "behind" along a
// circle-line dyad's line; "+" / "-" for a Newton block's det J.
std::string side_word(const LinkageSolver& solver, std::size_t b, int side);

// Moves dyad block b's joint in q to the dyad's other solution (mirrored across the line of its
// centres, or across the foot of its centre on its line). False for other blocks.
bool mirror_dyad(const LinkageSolver& solver, std::size_t b, Eigen::VectorXd& q);

// For dyads near their meeting point (margin below 1e-3 of the size), where a prediction alone
// cannot tell two crossing branches apart: on the smooth branch a dyad's side changes exactly where
// its margin touches zero like d^2 between the poses t0 and t (a crossing), and stays otherwise (a
// tangency touches like d^4). A solved q at t on the other side is moved to the dyad's other
// solution (the blocks after it by their closed form) and solved again to rounding, in place.
void keep_smooth_sides(const LinkageSolver& solver, double t0, const Eigen::VectorXd& q0, double t, Eigen::VectorXd& q);

// Above this kappa_2(J) the kinematics J gives are not to be trusted: a pose solved to rounding is
// still about eps kappa from the root, and J^-1 amplifies that by kappa again (eps kappa^2 ~ 1e-6
// here). On a crossing itself J's null direction is the difference of the two branches' tangents.
inline constexpr double singular_condition = 1e5;
// Above this one a pose is first solved to rounding before its kinematics (the residual test leaves
// a near-singular pose up to sqrt(2 L tol) from the root, and J's velocity moves with it).
inline constexpr double ill_condition = 1e4;

// Positions at s solved to rounding (||Phi||_inf <= 64 eps size) by full Newton from start.
std::optional<Eigen::VectorXd> solve_to_rounding(const LinkageSolver& solver, double s, const Eigen::VectorXd& start);

// Where the pose's branch is expected at driver s (a start for Newton).
using BranchGuess = std::function<Eigen::VectorXd(double)>;

// Velocity and acceleration at t as the 7-point stencils of positions at t + k h (k = -3..3), each
// solved to rounding from guess(t + k h). False when one does not solve.
bool branch_kinematics(const LinkageSolver& solver, double t, double h, const BranchGuess& guess, Eigen::VectorXd& velocity,
                       Eigen::VectorXd& acceleration);

}  // namespace numlab::mechanisms::detail
