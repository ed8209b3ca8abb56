#include "numlab/mechanisms/linkage/linkage_blocks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace numlab::mechanisms {

std::string_view to_string(BlockKind kind) {
  switch (kind) {
    case BlockKind::crank: return "crank, explicit";
    case BlockKind::body_point: return "body point, explicit";
    case BlockKind::slider: return "driven slider, explicit";
    case BlockKind::circle_circle: return "dyad, closed form (circle-circle)";
    case BlockKind::circle_line: return "dyad, closed form (circle-line)";
    case BlockKind::newton: return "Newton";
    case BlockKind::slot_pivot: return "slotted link, closed form (through a known joint)";
  }
  return "?";
}

namespace {

int constraint_of_row(const LinkageModel& model, int row) {
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const int first = model.first_row(static_cast<int>(k));
    if (row >= first && row < first + model.constraints()[k].rows()) return static_cast<int>(k);
  }
  return -1;
}

// A distance J-K and a slot on the line K-J (either way round) holding a joint A other than J: the
// block's joint J turns about K with the slot through A (the Whitworth's slotted link).
bool slot_through_known_joint(const LinkageModel& model, const LinkageBlock& block) {
  const int joint = block.joints[0];
  const Constraint* distance = nullptr;
  const Constraint* slot = nullptr;
  for (int k : block.constraints) {
    const Constraint& c = model.constraints()[static_cast<std::size_t>(k)];
    (c.kind == ConstraintKind::distance ? distance : slot) = &c;
  }
  const int centre = distance->joints[0] == joint ? distance->joints[1] : distance->joints[0];
  const auto [held, from, to] = slot->joints;
  return held != joint && ((from == centre && to == joint) || (from == joint && to == centre));
}

BlockKind kind_of(const LinkageModel& model, const LinkageBlock& block) {
  if (block.joints.size() != 1) return BlockKind::newton;
  std::vector<ConstraintKind> kinds;
  for (int k : block.constraints) kinds.push_back(model.constraints()[static_cast<std::size_t>(k)].kind);
  std::sort(kinds.begin(), kinds.end());
  using K = ConstraintKind;
  if (kinds == std::vector<K>{K::crank}) return BlockKind::crank;
  if (kinds == std::vector<K>{K::body_point}) return BlockKind::body_point;
  if (kinds == std::vector<K>{K::slider_line, K::slider_travel}) return BlockKind::slider;
  if (kinds == std::vector<K>{K::distance, K::distance}) return BlockKind::circle_circle;
  if (kinds == std::vector<K>{K::distance, K::slider_line}) return BlockKind::circle_line;
  if (kinds == std::vector<K>{K::distance, K::slider_on_line} && slot_through_known_joint(model, block)) return BlockKind::slot_pivot;
  return BlockKind::newton;
}

}  // namespace

std::vector<LinkageBlock> linkage_blocks(const LinkageModel& model) {
  std::vector<LinkageBlock> blocks;
  for (nonlinear::Block& order : nonlinear::block_triangular_order(model.pattern())) {
    LinkageBlock block;
    std::sort(order.unknowns.begin(), order.unknowns.end());
    std::sort(order.equations.begin(), order.equations.end());
    for (int column : order.unknowns) {
      const int joint = model.moving()[static_cast<std::size_t>(column / 2)];
      if (std::find(block.joints.begin(), block.joints.end(), joint) == block.joints.end()) block.joints.push_back(joint);
    }
    for (int row : order.equations) {
      const int k = constraint_of_row(model, row);
      if (std::find(block.constraints.begin(), block.constraints.end(), k) == block.constraints.end()) block.constraints.push_back(k);
    }
    for (int k : block.constraints) {
      for (int joint : model.constraints()[static_cast<std::size_t>(k)].joints) {
        if (joint < 0 || std::find(block.joints.begin(), block.joints.end(), joint) != block.joints.end()) continue;
        if (std::find(block.known_joints.begin(), block.known_joints.end(), joint) == block.known_joints.end()) {
          block.known_joints.push_back(joint);
        }
      }
    }
    block.rows_and_columns = std::move(order);
    block.kind = kind_of(model, block);
    blocks.push_back(std::move(block));
  }
  return blocks;
}

std::string describe_block(const LinkageModel& model, const LinkageBlock& block) {
  const auto names = [&](const std::vector<int>& joints) {
    std::vector<std::string> out;
    for (int j : joints) out.push_back(model.description().joints[static_cast<std::size_t>(j)].name);
    return fmt::format("{}", fmt::join(out, ", "));
  };
  const std::string from = block.known_joints.empty() ? "" : " from (" + names(block.known_joints) + ")";
  if (block.kind == BlockKind::newton) {
    const auto n = block.rows_and_columns.unknowns.size();
    return fmt::format("{}{}: {}x{} block, Newton", names(block.joints), from, n, n);
  }
  return fmt::format("{}{}: {}", names(block.joints), from, to_string(block.kind));
}

}  // namespace numlab::mechanisms
