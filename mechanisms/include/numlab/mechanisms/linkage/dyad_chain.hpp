#pragma once
// A linkage description of any size, for measuring how a sweep's time grows with the number of
// joints (`numlab bench linkage-scaling`, docs/performance.md): a Grashof crank-rocker four-bar
// (ground O, Q; crank O-A; coupler A-B; rocker Q-B, the lengths of mechanisms/models/four-bar.toml)
// carrying a strip of equilateral triangles on its coupler: each further joint P_k is a dyad on
// the two joints before it, both links of the coupler's length 4. The strip is rigid, so every pose
// the four-bar reaches assembles; each dyad is a block of its own (closed form, circle-circle), and
// J is block triangular with 2x2 diagonal blocks.

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace numlab::mechanisms {

// The TOML text of a chain with `joints` joints in all (ground ones included, 4 to 1000): O, Q, A,
// B and joints - 4 strip joints P1, P2, ...; the rough positions are the exact reference pose
// (crank at 60 degrees, B above the ground line, the strip going on away from the ground).
inline std::string dyad_chain_description(int joints) {
  if (joints < 4 || joints > 1000) throw std::invalid_argument(fmt::format("a dyad chain has 4 to 1000 joints, not {}", joints));
  const double crank = 1.5, coupler = 4.0, rocker = 3.5, ground = 4.5;
  const double angle = 60.0 * std::numbers::pi / 180.0;
  const Eigen::Vector2d O(0.0, 0.0), Q(ground, 0.0), A = O + crank * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  // B: the circles about A (coupler) and Q (rocker) meet; the point above the ground line.
  const Eigen::Vector2d AQ = Q - A;
  const double d = AQ.norm();
  const double along = (coupler * coupler - rocker * rocker + d * d) / (2.0 * d);
  const double across = std::sqrt(coupler * coupler - along * along);
  const Eigen::Vector2d unit = AQ / d, normal(-unit.y(), unit.x());
  const Eigen::Vector2d B1 = A + along * unit + across * normal, B2 = A + along * unit - across * normal;
  const Eigen::Vector2d B = B1.y() > B2.y() ? B1 : B2;
  std::vector<Eigen::Vector2d> points = {A, B};
  std::vector<std::string> names = {"A", "B"};
  std::string text = fmt::format(
      "[linkage]\nname = \"dyad-chain-{}\"\ntitle = \"a four-bar carrying a strip of {} triangles\"\n\n"
      "[ground]\nO = [0.0, 0.0]\nQ = [{:.17g}, 0.0]\n\n[joints]\n",
      joints, joints - 4, ground);
  std::string links = fmt::format(
      "[[link]]\njoints = [\"O\", \"A\"]\nlength = {:.17g}\n\n[[link]]\njoints = [\"A\", \"B\"]\nlength = {:.17g}\n\n"
      "[[link]]\njoints = [\"Q\", \"B\"]\nlength = {:.17g}\n\n",
      crank, coupler, rocker);
  for (int k = 1; k <= joints - 4; ++k) {
    const Eigen::Vector2d& p = points[points.size() - 2];
    const Eigen::Vector2d& r = points[points.size() - 1];
    // The apex of the equilateral triangle on p-r, on the side away from the joint before p (the
    // strip goes straight on); the first one on the side away from the ground pivot O.
    const Eigen::Vector2d middle = 0.5 * (p + r), base = r - p;
    const Eigen::Vector2d up = std::sqrt(3.0) / 2.0 * Eigen::Vector2d(-base.y(), base.x());
    const Eigen::Vector2d away_from = points.size() >= 3 ? points[points.size() - 3] : O;
    const Eigen::Vector2d plus = middle + up, minus = middle - up;
    const Eigen::Vector2d apex = (plus - away_from).squaredNorm() >= (minus - away_from).squaredNorm() ? plus : minus;
    const std::string name = fmt::format("P{}", k);
    text += fmt::format("{} = [{:.17g}, {:.17g}]\n", name, apex.x(), apex.y());
    links += fmt::format("[[link]]\njoints = [\"{}\", \"{}\"]\nlength = {:.17g}\n\n[[link]]\njoints = [\"{}\", \"{}\"]\nlength = {:.17g}\n\n",
                         names[names.size() - 2], name, coupler, names[names.size() - 1], name, coupler);
    points.push_back(apex);
    names.push_back(name);
  }
  text += fmt::format("A = [{:.17g}, {:.17g}]\nB = [{:.17g}, {:.17g}]\n\n", A.x(), A.y(), B.x(), B.y());
  return text + links + "[driver]\ntype = \"crank\"\npivot = \"O\"\njoint = \"A\"\nangle = 60.0\n";
}

}  // namespace numlab::mechanisms
