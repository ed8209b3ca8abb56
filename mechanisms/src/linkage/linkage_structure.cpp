#include "numlab/mechanisms/linkage/linkage_structure.hpp"

#include <fmt/format.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "numlab/mechanisms/linkage/linkage_authoring_checks.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"

namespace numlab::mechanisms {

std::string Mobility::formula() const {
  return fmt::format("3 (n - 1) - 2 j1 = 3 ({} - 1) - 2 ({}) = {}", members, lower_pairs, mobility);
}

Mobility gruebler_kutzbach(const LinkageDescription& d) {
  std::vector<int> members_at(d.joints.size(), 0);
  for (std::size_t j = 0; j < d.joints.size(); ++j) members_at[j] = d.joints[j].ground ? 1 : 0;
  for (const LinkSpec& link : d.links) {
    ++members_at[static_cast<std::size_t>(link.first)];
    ++members_at[static_cast<std::size_t>(link.second)];
  }
  for (const BodySpec& body : d.bodies) {
    for (int joint : body.joints) ++members_at[static_cast<std::size_t>(joint)];
  }
  for (const SliderSpec& slider : d.sliders) ++members_at[static_cast<std::size_t>(slider.joint)];
  // An actuator is two members, its cylinder pinned at one joint and its rod at the other.
  int actuators = 0;
  for (const DriverSpec* driver : drivers_of(d)) {
    if (driver->kind != DriverKind::actuator) continue;
    ++actuators;
    ++members_at[static_cast<std::size_t>(driver->from)], ++members_at[static_cast<std::size_t>(driver->joint)];
  }
  Mobility m;
  m.members = 1 + static_cast<int>(d.links.size() + d.bodies.size() + d.sliders.size()) + 2 * actuators;
  for (int k : members_at) m.lower_pairs += std::max(k - 1, 0);
  m.lower_pairs += static_cast<int>(d.sliders.size()) + actuators;  // each slider block's and cylinder's prismatic pair
  m.mobility = 3 * (m.members - 1) - 2 * m.lower_pairs;
  return m;
}

double held_distance(const LinkageDescription& d, int a, int b) {
  for (const LinkSpec& link : d.links) {
    if ((link.first == a && link.second == b) || (link.first == b && link.second == a)) return link.length;
  }
  for (const BodySpec& body : d.bodies) {
    const auto at = [&](int j) { return std::find(body.joints.begin(), body.joints.end(), j) - body.joints.begin(); };
    const auto p = at(a), q = at(b);
    if (p < static_cast<long>(body.joints.size()) && q < static_cast<long>(body.joints.size())) {
      return (body.local[static_cast<std::size_t>(q)] - body.local[static_cast<std::size_t>(p)]).norm();
    }
  }
  return -1.0;
}

double crank_radius(const LinkageDescription& d) { return crank_radius(d, d.driver); }

double crank_radius(const LinkageDescription& d, const DriverSpec& driver) {
  if (const double radius = held_distance(d, driver.pivot, driver.joint); radius > 0.0) return radius;
  throw LinkageFileError(d.file, driver.place, "the crank's joint is not on a link or body with its pivot");
}

std::vector<const DriverSpec*> drivers_of(const LinkageDescription& d) {
  std::vector<const DriverSpec*> drivers{&d.driver};
  if (d.second_driver) drivers.push_back(&*d.second_driver);
  return drivers;
}

namespace {

using Pattern = Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>;

// Maximum matching of rows to columns by augmenting paths (Kuhn): row_of[c], column_of[r], -1 if free.
struct Matching {
  std::vector<int> row_of, column_of;
};

bool augment(const Pattern& pattern, int row, std::vector<char>& seen, Matching& m) {
  for (int c = 0; c < pattern.cols(); ++c) {
    if (!pattern(row, c) || seen[static_cast<std::size_t>(c)]) continue;
    seen[static_cast<std::size_t>(c)] = 1;
    const int other = m.row_of[static_cast<std::size_t>(c)];
    if (other < 0 || augment(pattern, other, seen, m)) {
      m.row_of[static_cast<std::size_t>(c)] = row;
      m.column_of[static_cast<std::size_t>(row)] = c;
      return true;
    }
  }
  return false;
}

Matching maximum_matching(const Pattern& pattern) {
  Matching m{std::vector<int>(static_cast<std::size_t>(pattern.cols()), -1),
             std::vector<int>(static_cast<std::size_t>(pattern.rows()), -1)};
  for (int r = 0; r < pattern.rows(); ++r) {
    std::vector<char> seen(static_cast<std::size_t>(pattern.cols()), 0);
    augment(pattern, r, seen, m);
  }
  return m;
}

// From the free columns of `pattern` (its unknowns without an equation: under-constrained),
// everything reachable by alternating paths: the part of the system that cannot be solved.
// `partner_of_column` / `partner_of_row` are the matching's two sides. Called on the transposed
// pattern with the sides swapped, it starts from the free equations instead (over-constrained).
void reach_from_free(const Pattern& pattern, const std::vector<int>& partner_of_column,
                     const std::vector<int>& partner_of_row, std::set<int>& rows, std::set<int>& columns) {
  std::vector<int> stack;
  for (int c = 0; c < pattern.cols(); ++c) {
    if (partner_of_column[static_cast<std::size_t>(c)] < 0) stack.push_back(c), columns.insert(c);
  }
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    for (int r = 0; r < pattern.rows(); ++r) {
      if (!pattern(r, c) || !rows.insert(r).second) continue;
      const int next = partner_of_row[static_cast<std::size_t>(r)];
      if (next >= 0 && columns.insert(next).second) stack.push_back(next);
    }
  }
}

std::string plural(std::size_t count, const char* word) { return fmt::format("{} {}{}", count, word, count == 1 ? "" : "s"); }

// "joints C, D" (the joints of the columns) or, when no unknown is involved, the rows' items.
std::string who(const LinkageModel& model, const std::set<int>& rows, const std::set<int>& columns) {
  std::vector<std::string> names;
  if (!columns.empty()) {
    for (int c : columns) {
      const std::string& name = model.description().joints[static_cast<std::size_t>(model.moving()[static_cast<std::size_t>(c / 2)])].name;
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return fmt::format("{} {}", names.size() == 1 ? "joint" : "joints", fmt::join(names, ", "));
  }
  for (int r : rows) names.push_back(model.row_name(r));
  return fmt::format("{}", fmt::join(names, ", "));
}

// The place of the first constraint among rows, or of the first joint among columns.
SourcePlace first_place(const LinkageModel& model, const std::set<int>& rows, const std::set<int>& columns) {
  if (!columns.empty()) {
    return model.description().joints[static_cast<std::size_t>(model.moving()[static_cast<std::size_t>(*columns.begin() / 2)])].place;
  }
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const int first = model.first_row(static_cast<int>(k));
    if (!rows.empty() && *rows.begin() >= first && *rows.begin() < first + model.constraints()[k].rows()) {
      return model.constraints()[k].place;
    }
  }
  return {};
}

std::size_t matched_count(const Matching& m) {
  return static_cast<std::size_t>(std::count_if(m.column_of.begin(), m.column_of.end(), [](int c) { return c >= 0; }));
}

bool same_place(SourcePlace a, SourcePlace b) { return a.line == b.line && a.column == b.column; }

// The pattern without the rows of the item at `place` (a body gives several constraints, all at
// its place).
Pattern without_item(const LinkageModel& model, const Pattern& pattern, SourcePlace place) {
  Pattern out = pattern;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    if (!same_place(model.constraints()[k].place, place)) continue;
    out.middleRows(model.first_row(static_cast<int>(k)), model.constraints()[k].rows()).setConstant(false);
  }
  return out;
}

// The numerical rank of J at the rough positions without the rows of the item at `place` (J's rows
// are dimensionless gradients, so the threshold does not depend on the file's unit).
int rank_without_item(const LinkageModel& model, const Eigen::MatrixXd& jacobian, SourcePlace place) {
  Eigen::MatrixXd J = jacobian;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    if (same_place(model.constraints()[k].place, place)) {
      J.middleRows(model.first_row(static_cast<int>(k)), model.constraints()[k].rows()).setZero();
    }
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  qr.setThreshold(1e-9);
  return static_cast<int>(qr.rank());
}

// Of the items with rows in the over-constrained part (`rows`), the one the others do not need:
// without it the matching is as large and, at the rough positions, J's rank too (a link beside a
// body that already holds its two joints: not the rocker that makes the body's pair redundant).
// The last such item in the file; -1 when no single item is.
int redundant_item(const LinkageModel& model, const Pattern& pattern, std::size_t matched, const std::set<int>& rows) {
  Eigen::MatrixXd J;
  model.jacobian(model.unknowns(model.rough_positions()), model.driver_from_user(model.description().driver.reference), J);
  const int rank = rank_without_item(model, J, SourcePlace{-1, -1});
  int found = -1;
  bool found_keeps_rank = false;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const Constraint& c = model.constraints()[k];
    const int first = model.first_row(static_cast<int>(k));
    if (rows.lower_bound(first) == rows.lower_bound(first + c.rows())) continue;  // no row of it in the part
    if (matched_count(maximum_matching(without_item(model, pattern, c.place))) != matched) continue;
    const bool keeps_rank = rank_without_item(model, J, c.place) == rank;
    if (found < 0 || keeps_rank > found_keeps_rank ||
        (keeps_rank == found_keeps_rank && c.place.line >= model.constraints()[static_cast<std::size_t>(found)].place.line)) {
      found = static_cast<int>(k);
      found_keeps_rank = keeps_rank;
    }
  }
  return found;
}

// The reference pose the other items give without the [[link]] or [[body]] at `place`: the model
// without it, solved from the rough positions (to a tolerance relative to its size). Nothing when
// the item is neither, or the others hold no pose by themselves (still over- or under-constrained,
// or they do not assemble).
std::optional<JointPositions> pose_without(const LinkageModel& model, SourcePlace place) {
  LinkageDescription reduced = model.description();
  const auto at_place = [&](const auto& item) { return same_place(item.place, place); };
  if (std::erase_if(reduced.links, at_place) + std::erase_if(reduced.bodies, at_place) == 0) return std::nullopt;
  try {
    const LinkageModel without(std::move(reduced));
    const LinkageSolver solver(without, LinkageSolverOptions{});
    return without.positions(polished_reference(without, solver.reference()));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The pose is solved to 1e-11 of the size: a distance within 1e-6 of the item's agrees.
constexpr double agreement = 1e-6;

// A redundant [[link]] against the pose the others give: it agrees (redundant) or asks for another
// distance (contradicts them).
std::string link_verdict(const LinkSpec& link, const JointPositions& pose, const std::string& name, const std::string& with) {
  const double distance = (pose[static_cast<std::size_t>(link.first)] - pose[static_cast<std::size_t>(link.second)]).norm();
  if (std::abs(distance - link.length) > agreement * std::max(distance, link.length)) {
    return fmt::format("{} contradicts the other items: {}; without it they hold its joints {:.6g} apart, it asks for {:.6g}",
                       name, with, distance, link.length);
  }
  return fmt::format("{} is redundant: {}; the other items already hold its joints {:.6g} apart, its own length", name,
                     with, distance);
}

// A redundant [[body]] against the pose the others give: the pair of its joints whose distance
// there differs most from its local coordinates' (contradicts them), else its turn: held as its
// mirror image (contradicts them) or in its own shape (redundant, named with its longest pair).
std::string body_verdict(const LinkageDescription& d, const BodySpec& body, const JointPositions& pose,
                         const std::string& name, const std::string& with) {
  struct Pair {
    std::size_t first = 0, second = 1;
    double own = 0.0, held = 0.0;
  };
  Pair worst, longest;
  for (std::size_t i = 0; i < body.joints.size(); ++i) {
    for (std::size_t j = i + 1; j < body.joints.size(); ++j) {
      const Pair p{i, j, (body.local[i] - body.local[j]).norm(),
                   (pose[static_cast<std::size_t>(body.joints[i])] - pose[static_cast<std::size_t>(body.joints[j])]).norm()};
      if (std::abs(p.held - p.own) > std::abs(worst.held - worst.own)) worst = p;
      if (p.own > longest.own) longest = p;
    }
  }
  const auto joint_name = [&](std::size_t k) { return d.joints[static_cast<std::size_t>(body.joints[k])].name; };
  if (std::abs(worst.held - worst.own) > agreement * longest.own) {
    return fmt::format("{} contradicts the other items: {}; without it they hold joints {} and {} {:.6g} apart, its "
                       "local coordinates ask for {:.6g}",
                       name, with, joint_name(worst.first), joint_name(worst.second), worst.held, worst.own);
  }
  const BodyTurn turn = body_turn(body, pose);
  if (turn.mirrored(0.0)) {
    return fmt::format("{} contradicts the other items: {}; without it they hold its joints at its local distances but "
                       "as their mirror image ({})",
                       name, with, turn.text(d, "the others' pose"));
  }
  return fmt::format("{} is redundant: {}; the other items already hold its joints in its local shape (all {} distances; "
                     "{} and {} {:.6g} apart)",
                     name, with, body.joints.size() * (body.joints.size() - 1) / 2, joint_name(longest.first),
                     joint_name(longest.second), longest.held);
}

// "link A-B is redundant: with it, joints A, B have 5 equations for 4 unknowns; ..." at the item's
// place (a body is named as a whole: "body plate"). A [[link]] or [[body]] is measured against the
// pose the other items give: one that agrees is redundant, one that does not contradicts them.
StructuralProblem redundancy(const LinkageModel& model, int item, const std::set<int>& rows, const std::set<int>& columns,
                             const std::string& count) {
  const LinkageDescription& d = model.description();
  const Constraint& c = model.constraints()[static_cast<std::size_t>(item)];
  const std::string joints = who(model, rows, columns);
  const std::string name = c.name.substr(0, c.name.find(':'));
  const std::string with = fmt::format("with it, {} {} {}", joints, joints.find(',') == std::string::npos ? "has" : "have", count);
  if (const std::optional<JointPositions> pose = pose_without(model, c.place)) {
    const auto at_place = [&](const auto& spec) { return same_place(spec.place, c.place); };
    if (const auto link = std::find_if(d.links.begin(), d.links.end(), at_place); link != d.links.end()) {
      return {link_verdict(*link, *pose, name, with), c.place};
    }
    if (const auto body = std::find_if(d.bodies.begin(), d.bodies.end(), at_place); body != d.bodies.end()) {
      return {body_verdict(d, *body, *pose, name, with), c.place};
    }
  }
  return {fmt::format("{} is redundant: {}; the other items already hold them", name, with), c.place};
}

}  // namespace

StructuralProblem structural_problem(const LinkageModel& model) {
  const Pattern pattern = model.pattern();
  const Matching m = maximum_matching(pattern);
  std::set<int> rows, columns;
  reach_from_free(pattern, m.row_of, m.column_of, rows, columns);
  const bool over = columns.empty();
  if (over) reach_from_free(pattern.transpose(), m.column_of, m.row_of, columns, rows);
  if (rows.empty() && columns.empty()) return {};
  const std::string count = fmt::format("{} for {}", plural(rows.size(), "equation"), plural(columns.size(), "unknown"));
  if (over && !columns.empty()) {
    if (const int item = redundant_item(model, pattern, matched_count(m), rows); item >= 0) {
      return redundancy(model, item, rows, columns, count);
    }
  }
  return {who(model, rows, columns) + ": " + count, first_place(model, rows, columns)};
}

void require_one_degree_of_freedom(const LinkageModel& model) {
  const LinkageDescription& d = model.description();
  const Mobility mobility = gruebler_kutzbach(d);
  const StructuralProblem problem = structural_problem(model);
  const int inputs = d.second_driver ? 2 : 1;
  const std::string mobility_text = fmt::format("mobility {} (Gruebler-Kutzbach {}), {} {}", mobility.mobility,
                                                mobility.formula(), inputs == 1 ? "one driver needs" : "two drivers need", inputs);
  if (!problem.text.empty()) {
    throw LinkageFileError(d.file, problem.place,
                           problem.text + (mobility.mobility == inputs ? "" : "; " + mobility_text));
  }
  if (mobility.mobility != inputs) throw LinkageFileError(d.file, {}, mobility_text);
}

}  // namespace numlab::mechanisms
