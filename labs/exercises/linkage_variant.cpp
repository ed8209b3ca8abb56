#include "exercises/linkage_variant.hpp"

#include <string>
#include <utility>
#include <vector>

#include "exercises/variant_lengths.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::LinkageDescription;

// The first ground joint (it stays) and the others (their offsets from it vary).
std::pair<std::size_t, std::vector<std::size_t>> ground_joints(const LinkageDescription& d) {
  std::vector<std::size_t> ground;
  for (std::size_t j = 0; j < d.joints.size(); ++j) {
    if (d.joints[j].ground) ground.push_back(j);
  }
  if (ground.empty()) return {0, {}};
  return {ground.front(), std::vector<std::size_t>(ground.begin() + 1, ground.end())};
}

// Every number a variant perturbs, in one order: links, bodies' local coordinates, ground offsets.
LinkLengths numbers_of(const LinkageDescription& d) {
  LinkLengths numbers;
  for (std::size_t k = 0; k < d.links.size(); ++k) numbers.push_back({"link " + std::to_string(k), d.links[k].length});
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    for (std::size_t j = 0; j < d.bodies[b].local.size(); ++j) {
      for (int axis = 0; axis < 2; ++axis) {
        numbers.push_back({"body " + std::to_string(b) + " " + std::to_string(j) + " " + std::to_string(axis),
                           d.bodies[b].local[j](axis)});
      }
    }
  }
  const auto [first, others] = ground_joints(d);
  for (std::size_t j : others) {
    for (int axis = 0; axis < 2; ++axis) {
      numbers.push_back({"ground " + std::to_string(j) + " " + std::to_string(axis),
                         d.joints[j].position(axis) - d.joints[first].position(axis)});
    }
  }
  return numbers;
}

// The description with `numbers` (numbers_of's order) in place of the file's.
LinkageDescription with_numbers(LinkageDescription d, const LinkLengths& numbers) {
  std::size_t at = 0;
  for (auto& link : d.links) link.length = numbers[at++].value;
  for (auto& body : d.bodies) {
    for (auto& local : body.local) {
      local.x() = numbers[at++].value;
      local.y() = numbers[at++].value;
    }
  }
  const auto [first, others] = ground_joints(d);
  for (std::size_t j : others) {
    const Eigen::Vector2d origin = d.joints[first].position;
    d.joints[j].position.x() = origin.x() + numbers[at++].value;
    d.joints[j].position.y() = origin.y() + numbers[at++].value;
  }
  return d;
}

}  // namespace

std::shared_ptr<const mechanisms::LinkageModel> linkage_variant(
    std::shared_ptr<const mechanisms::LinkageModel> file, const Variant& variant,
    const std::function<bool(std::shared_ptr<const mechanisms::LinkageModel>)>& valid) {
  if (!variant.active()) return file;
  const LinkageDescription& d = file->description();
  auto model_of = [&d](const LinkLengths& numbers) {
    return std::make_shared<const mechanisms::LinkageModel>(with_numbers(d, numbers));
  };
  const LinkLengths drawn = variant_lengths(variant, 11, numbers_of(d), [&](const LinkLengths& numbers) {
    try {
      return valid(model_of(numbers));
    } catch (const std::invalid_argument&) {
      return false;  // not a mechanism of one degree of freedom (cannot happen at 3%, but never trusted)
    }
  });
  return model_of(drawn);
}

}  // namespace numlab::exercises
