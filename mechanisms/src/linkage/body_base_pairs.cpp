#include "numlab/mechanisms/linkage/body_base_pairs.hpp"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::mechanisms {

namespace {

bool known(const std::vector<int>& round, int joint) { return round[static_cast<std::size_t>(joint)] >= 0; }

// Step 4: each body's two joints known first; a tie (or never known) by name. The two keep the
// file's order (which one is b0 changes the rows, not the blocks).
std::vector<std::array<int, 2>> pairs_from(const LinkageDescription& d, const std::vector<int>& round) {
  std::vector<std::array<int, 2>> pairs;
  for (const BodySpec& body : d.bodies) {
    const auto rank = [&](int k) {
      const auto joint = static_cast<std::size_t>(body.joints[static_cast<std::size_t>(k)]);
      return std::pair<int, const std::string&>(round[joint] < 0 ? INT_MAX : round[joint], d.joints[joint].name);
    };
    std::vector<int> order(body.joints.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
    pairs.push_back({std::min(order[0], order[1]), std::max(order[0], order[1])});  // as the file lists them
  }
  return pairs;
}

// Step 2: the unknown joints that two rows fix from known joints.
std::vector<int> fixed_by_rows(const LinkageModel& model, const std::vector<int>& round) {
  const LinkageDescription& d = model.description();
  std::vector<int> rows(d.joints.size(), 0);
  // 2a. An item other than a body: its rows count for its one unknown joint, if it has one.
  for (const Constraint& c : model.constraints()) {
    if (c.body >= 0) continue;
    int unknown = -1, unknowns = 0;
    for (int joint : c.joints) {
      if (joint >= 0 && !known(round, joint)) unknown = joint, ++unknowns;
    }
    if (unknowns == 1) rows[static_cast<std::size_t>(unknown)] += c.rows();
  }
  // 2b. A body with one known joint gives its other joints a distance; with two, it places them.
  for (const BodySpec& body : d.bodies) {
    const auto held = std::count_if(body.joints.begin(), body.joints.end(), [&](int j) { return known(round, j); });
    for (int joint : body.joints) rows[static_cast<std::size_t>(joint)] += static_cast<int>(std::min<std::ptrdiff_t>(held, 2));
  }
  std::vector<int> fixed;
  for (std::size_t j = 0; j < d.joints.size(); ++j) {
    if (!known(round, static_cast<int>(j)) && rows[j] >= 2) fixed.push_back(static_cast<int>(j));
  }
  return fixed;
}

// The smallest blocks of the model with `pairs` that need only known joints: their size (in joints)
// and their joints. None (size SIZE_MAX) when that model has no block order (it is not regular).
struct ReadyBlocks {
  std::size_t size = SIZE_MAX;
  std::vector<int> joints;
};
ReadyBlocks smallest_ready(const LinkageDescription& d, const std::vector<std::array<int, 2>>& pairs, const std::vector<int>& round) {
  std::vector<LinkageBlock> blocks;
  try {
    blocks = linkage_blocks(LinkageModel(d, pairs));
  } catch (const std::invalid_argument&) {
    return {};
  }
  const auto ready = [&](const LinkageBlock& block) {
    return std::none_of(block.joints.begin(), block.joints.end(), [&](int j) { return known(round, j); }) &&
           std::all_of(block.known_joints.begin(), block.known_joints.end(), [&](int j) { return known(round, j); });
  };
  ReadyBlocks out;
  for (const LinkageBlock& block : blocks) {
    if (ready(block)) out.size = std::min(out.size, block.joints.size());
  }
  for (const LinkageBlock& block : blocks) {
    if (ready(block) && block.joints.size() == out.size) out.joints.insert(out.joints.end(), block.joints.begin(), block.joints.end());
  }
  return out;
}

// A body's joints (indices into its list) in the order of their names.
std::vector<int> by_name(const LinkageDescription& d, const BodySpec& body) {
  std::vector<int> order(body.joints.size());
  std::iota(order.begin(), order.end(), 0);
  const auto name = [&](int k) -> const std::string& { return d.joints[static_cast<std::size_t>(body.joints[static_cast<std::size_t>(k)])].name; };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return name(a) < name(b); });
  return order;
}

// Step 3: the joints of the smallest blocks that need only known joints, in the model with the
// pairs chosen so far. A body with a joint in them may have a pair that makes them smaller (a pair
// from outside the block ties its rows to joints found later): each of its pairs is tried, one
// body at a time, bodies and pairs in the order of their joints' names, and a smaller block kept.
std::vector<int> solved_by_newton(const LinkageModel& model, const std::vector<int>& round) {
  const LinkageDescription& d = model.description();
  std::vector<std::array<int, 2>> pairs = pairs_from(d, round);
  ReadyBlocks best = smallest_ready(d, pairs, round);
  std::vector<std::size_t> bodies(d.bodies.size());
  std::iota(bodies.begin(), bodies.end(), std::size_t{0});
  const auto names = [&](std::size_t b) {
    std::vector<std::string> list;
    for (int j : d.bodies[b].joints) list.push_back(d.joints[static_cast<std::size_t>(j)].name);
    std::sort(list.begin(), list.end());
    return list;
  };
  std::stable_sort(bodies.begin(), bodies.end(), [&](std::size_t a, std::size_t b) { return names(a) < names(b); });
  for (std::size_t b : bodies) {
    const BodySpec& body = d.bodies[b];
    const auto in_block = [&](int j) { return std::find(best.joints.begin(), best.joints.end(), j) != best.joints.end(); };
    if (std::none_of(body.joints.begin(), body.joints.end(), in_block)) continue;
    const std::vector<int> order = by_name(d, body);
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t k = i + 1; k < order.size(); ++k) {
        std::vector<std::array<int, 2>> trial = pairs;
        trial[b] = {std::min(order[i], order[k]), std::max(order[i], order[k])};
        if (trial[b] == pairs[b]) continue;
        ReadyBlocks tried = smallest_ready(d, trial, round);
        if (tried.size < best.size) best = std::move(tried), pairs = std::move(trial);
      }
    }
  }
  return best.joints;
}

}  // namespace

std::vector<int> known_rounds(const LinkageModel& model) {
  const LinkageDescription& d = model.description();
  // 1. The ground joints are known from the start.
  std::vector<int> round(d.joints.size(), -1);
  for (std::size_t j = 0; j < d.joints.size(); ++j) {
    if (d.joints[j].ground) round[j] = 0;
  }
  for (int r = 1;; ++r) {
    // 2. Joints fixed by two rows from known joints; 3. else the smallest blocks ready for Newton.
    std::vector<int> next = fixed_by_rows(model, round);
    if (next.empty()) next = solved_by_newton(model, round);
    if (next.empty()) return round;
    for (int joint : next) round[static_cast<std::size_t>(joint)] = r;
  }
}

std::vector<std::array<int, 2>> body_base_pairs(const LinkageModel& model) {
  return pairs_from(model.description(), known_rounds(model));
}

}  // namespace numlab::mechanisms
