#pragma once
// The order in which a linkage model can be solved piece by piece: nonlinear::block_triangular_order
// on the model's pattern, each block then named by what it is.
//
//   crank          the driven joint, explicit: p_A = p_O + r (cos t, sin t)
//   body point     a joint of a rigid body placed by two joints already known, explicit (linear)
//   slider         a driven slider's joint, explicit: p = P + s u
//   circle-circle  a dyad: a joint at two known distances from two known joints; closed form by
//                  circle intersection, on the side the reference pose picks
//   circle-line    a dyad: a joint at a known distance from a known joint and on a slider's line
//   newton         anything else (a block of several joints, as in a Stephenson III six-bar):
//                  Newton on the block's equations
//
// A joint's x and y always fall in one block (the pattern marks both), so a block is a set of joints.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/nonlinear/block_order.hpp"

namespace numlab::mechanisms {

// slot_pivot: a joint J at distance L from a known joint K, with the line K-J (a slotted link turning
// about K) passing through a known joint A at the slot's offset: J = K + L u, u the direction at
// which A sits at that offset from the line (two such directions; the one nearer the start).
enum class BlockKind { crank, body_point, slider, circle_circle, circle_line, newton, slot_pivot };

std::string_view to_string(BlockKind kind);

struct LinkageBlock {
  nonlinear::Block rows_and_columns;  // the block's equations (rows) and unknowns (columns)
  BlockKind kind = BlockKind::newton;
  std::vector<int> joints;            // the moving joints it solves, in unknown order
  std::vector<int> constraints;       // the constraints whose rows it holds
  std::vector<int> known_joints;      // joints outside the block its equations read (solved before)
  bool closed_form() const { return kind != BlockKind::newton; }
  // A crank, body point or driven slider: its joint is a formula of joints already known, placed
  // directly (no equation to solve, no Newton iteration) by every solver.
  bool placed_directly() const { return kind == BlockKind::crank || kind == BlockKind::body_point || kind == BlockKind::slider; }
  bool dyad() const { return kind == BlockKind::circle_circle || kind == BlockKind::circle_line; }
};

// Blocks in solving order. The model is square and structurally regular (LinkageModel checks).
std::vector<LinkageBlock> linkage_blocks(const LinkageModel& model);

// One line per block: "C from (P1, B): body point, explicit"; "E, F: 4x4 block, Newton".
std::string describe_block(const LinkageModel& model, const LinkageBlock& block);

}  // namespace numlab::mechanisms
