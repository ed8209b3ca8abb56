// The order of a file's joints must not change its model's blocks (issue 30 §1): every shipped
// model with bodies and Sylvester's skew pantograph, with every body's joints in every order and
// the [joints] and [ground] tables in three orders, give the same blocks (kinds, joints, the joints
// they are solved from) and the same poses over a sweep. The pantograph's own closed form checks
// the poses, and the file-order base pairs (the rule before body_base_pairs.hpp) are shown to lose
// its dyads, so the test can fail.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "../models/model_files.hpp"
#include "numlab/mechanisms/linkage/body_base_pairs.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string pantograph_path() { return std::string(NUMLAB_TEST_FILES_DIR) + "/skew-pantograph.toml"; }

// The file with the `name = [x, y]` lines of table `header` ("[joints]") in another order: 0 as
// written, 1 reversed, 2 the first moved to the end.
std::string reorder_table(const std::string& text, const std::string& header, int order) {
  std::istringstream in(text);
  std::vector<std::string> before, items, after;
  bool inside = false, done = false;
  for (std::string line; std::getline(in, line);) {
    if (!done && line == header) {
      inside = true;
      before.push_back(line);
      continue;
    }
    if (inside && !line.empty() && line[0] == '[') inside = false, done = true;
    if (inside && line.find('=') != std::string::npos && line[0] != '#') {
      items.push_back(line);
    } else {
      (done ? after : before).push_back(line);
    }
  }
  if (order == 1) std::reverse(items.begin(), items.end());
  if (order == 2 && !items.empty()) std::rotate(items.begin(), items.begin() + 1, items.end());
  std::string out;
  for (const auto* part : {&before, &items, &after}) {
    for (const std::string& line : *part) out += line + "\n";
  }
  return out;
}

LinkageDescription with_tables_in_order(const std::string& text, int order) {
  return parse_linkage_description(reorder_table(reorder_table(text, "[joints]", order), "[ground]", order), "reordered.toml");
}

// Body b's joints (and their local points) in the order `order` (indices into the file's list).
void reorder_body(LinkageDescription& d, std::size_t b, const std::vector<int>& order) {
  BodySpec& body = d.bodies[b];
  const BodySpec file = body;
  for (std::size_t k = 0; k < order.size(); ++k) {
    body.joints[k] = file.joints[static_cast<std::size_t>(order[k])];
    body.local[k] = file.local[static_cast<std::size_t>(order[k])];
  }
}

std::vector<std::vector<int>> permutations(std::size_t n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::vector<int>> all;
  do all.push_back(order);
  while (std::next_permutation(order.begin(), order.end()));
  return all;
}

std::string name_of(const LinkageModel& model, int joint) { return model.description().joints[static_cast<std::size_t>(joint)].name; }

// Every block as "kind: joints from known joints", names sorted, and the blocks sorted: what the
// order of the file's items must not change.
std::vector<std::string> block_summary(const LinkageModel& model) {
  std::vector<std::string> out;
  for (const LinkageBlock& block : linkage_blocks(model)) {
    const auto names = [&](const std::vector<int>& joints) {
      std::vector<std::string> list;
      for (int j : joints) list.push_back(name_of(model, j));
      std::sort(list.begin(), list.end());
      std::string text;
      for (const std::string& name : list) text += name + " ";
      return text;
    };
    out.push_back(std::string(to_string(block.kind)) + " " + std::to_string(block.rows_and_columns.unknowns.size()) + ": " +
                  names(block.joints) + "from " + names(block.known_joints));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::multiset<std::size_t> block_sizes(const LinkageModel& model) {
  std::multiset<std::size_t> sizes;
  for (const LinkageBlock& block : linkage_blocks(model)) sizes.insert(block.rows_and_columns.unknowns.size());
  return sizes;
}

bool every_block_closed(const LinkageModel& model) {
  const auto blocks = linkage_blocks(model);
  return std::all_of(blocks.begin(), blocks.end(), [](const LinkageBlock& b) { return b.closed_form(); });
}

// The sweep: a whole turn about the reference angle, or a quarter of the mechanism's size either
// side of the reference length; the Mustang closes on (-41.42, 56.45) deg only. Poses that do not
// assemble are compared by their status.
struct SweepRange {
  double start, stop, step;
};
SweepRange range_for(const std::string& name, const LinkageModel& model, double size) {
  if (name == "mustang") return {-40.0, 56.0, 8.0};
  const double reference = model.description().driver.reference;
  if (model.crank_driven()) return {reference - 180.0, reference + 180.0, 15.0};
  return {reference - 0.25 * size, reference + 0.25 * size, size / 48.0};
}

// A sweep by joint name: per pose, its status and each joint's position.
struct NamedSweep {
  std::vector<Status> status;
  std::vector<std::map<std::string, Eigen::Vector2d>> poses;
  std::vector<double> inverse_norms;  // ||J^-1||_2 per pose
  double tolerance = 0.0;             // the residual test, absolute (length units)
};

NamedSweep sweep_by_name(const LinkageModel& model, const std::string& solver, const SweepRange& range) {
  LinkageSolverOptions options;
  options.solver = solver;
  const LinkageSolver linkage(model, options);
  const LinkageSweep sweep = linkage_sweep(linkage, range.start, range.stop, range.step);
  NamedSweep out;
  out.tolerance = linkage.options().newton.residual_tolerance;
  for (const LinkagePose& pose : sweep.poses) {
    out.status.push_back(pose.outcome.status);
    std::map<std::string, Eigen::Vector2d> joints;
    const JointPositions p = model.positions(pose.q);
    for (std::size_t j = 0; j < p.size(); ++j) joints[model.description().joints[j].name] = p[j];
    out.poses.push_back(std::move(joints));
    const bool solved = pose.outcome.status == Status::converged;
    out.inverse_norms.push_back(solved ? inverse_jacobian_norm(model, model.driver_from_user(pose.driver), pose.q) : 0.0);
  }
  return out;
}

// The two sweeps' poses agree within what their residual tests allow: |dq| <= ||J^-1||_2 ||Phi||_2
// <= ||J^-1||_2 sqrt(n) tol for each of the two, a factor 10 spare, and the rounding of the
// positions (64 eps ||J^-1|| |J| |q|, |J| <= 2 for these rows, taken as 64 eps kappa |q|).
void require_same_poses(const NamedSweep& a, const NamedSweep& b, int unknowns, double size) {
  REQUIRE(a.poses.size() == b.poses.size());
  for (std::size_t k = 0; k < a.poses.size(); ++k) {
    INFO("pose " << k);
    REQUIRE(a.status[k] == b.status[k]);
    if (a.status[k] != Status::converged) continue;
    const double inverse = std::max(a.inverse_norms[k], b.inverse_norms[k]);
    const double bound = 10.0 * inverse * std::sqrt(static_cast<double>(unknowns)) * (a.tolerance + b.tolerance) +
                         64.0 * std::numeric_limits<double>::epsilon() * inverse * 2.0 * size;
    double worst = 0.0;
    for (const auto& [name, p] : a.poses[k]) worst = std::max(worst, (p - b.poses[k].at(name)).norm());
    INFO("pose " << k << ": joints " << worst << " apart, allowed " << bound);
    REQUIRE(std::isfinite(worst));
    CHECK(worst <= bound);
  }
}

struct Case {
  std::string name, text;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// Stephenson III with a fourth joint a2 on T2 (a body point once d, e, f are found), named before
// them: a pair chosen by name alone (a2, d) would tie a2 into the 6x6 block (an 8x8).
std::string stephenson_with_a2() {
  std::string text = text_of(model_path("stephenson-iii"));
  text = replaced(text, "f = [1.2, 4.4]\n", "f = [1.2, 4.4]\na2 = [3.4192388155425117, 2.5636038969321073]\n");
  return replaced(text, "joints = [\"d\", \"e\", \"f\"]\nlocal = [[0.0, 0.0], [2.1, 0.0], [-1.45, 1.0]]",
                  "joints = [\"d\", \"e\", \"f\", \"a2\"]\nlocal = [[0.0, 0.0], [2.1, 0.0], [-1.45, 1.0], [1.0, -0.5]]");
}

std::vector<Case> cases_with_bodies() {
  std::vector<Case> out;
  for (const std::string& name : shipped_model_names()) {
    if (!model_file(name).description().bodies.empty()) out.push_back({name, text_of(model_path(name))});
  }
  out.push_back({"skew-pantograph", text_of(pantograph_path())});
  out.push_back({"stephenson-iii with a2", stephenson_with_a2()});
  return out;
}

}  // namespace

TEST_CASE("Joint order: every order of each body's joints and of the tables gives the same blocks", "[linkage-joint-order]") {
  const std::vector<Case> cases = cases_with_bodies();
  REQUIRE(cases.size() >= 9);  // jansen, mustang, klann, chebyshev, hoeken, watt-i, stephenson-iii, the pantograph, a2
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string& text = c.text;
    const LinkageModel file(parse_linkage_description(text, c.name + ".toml"));
    const std::vector<std::string> expected = block_summary(file);
    const std::multiset<std::size_t> sizes = block_sizes(file);
    std::vector<std::vector<std::vector<int>>> orders;  // per body, every order of its joints
    for (const BodySpec& body : file.description().bodies) orders.push_back(permutations(body.joints.size()));
    int models = 0, mismatches = 0;
    for (int table_order = 0; table_order < 3; ++table_order) {
      const LinkageDescription tables = with_tables_in_order(text, table_order);
      // Every combination of the bodies' orders (an odometer over the bodies).
      std::vector<std::size_t> pick(orders.size(), 0);
      for (bool more = true; more; ++models) {
        LinkageDescription d = tables;
        for (std::size_t b = 0; b < orders.size(); ++b) reorder_body(d, b, orders[b][pick[b]]);
        const LinkageModel model(std::move(d));
        CHECK(block_sizes(model) == sizes);
        if (block_summary(model) != expected && ++mismatches <= 3) {
          std::string where = "table order " + std::to_string(table_order) + ", bodies";
          for (const BodySpec& body : model.description().bodies) {
            for (int j : body.joints) where += " " + name_of(model, j);
            where += ";";
          }
          FAIL_CHECK(where);
        }
        more = false;
        for (std::size_t b = 0; b < pick.size() && !more; ++b) {
          if (++pick[b] < orders[b].size()) more = true;
          else pick[b] = 0;
        }
      }
    }
    INFO(models << " orders");
    CHECK(models >= 3 * 6);
    CHECK(mismatches == 0);
  }
}

TEST_CASE("Joint order: the poses of a sweep do not depend on the order either", "[linkage-joint-order]") {
  for (const Case& c : cases_with_bodies()) {
    INFO(c.name);
    const std::string& text = c.text;
    const LinkageModel file(parse_linkage_description(text, c.name + ".toml"));
    // The analytic solver where every block has a closed form, and full Newton always.
    std::vector<std::string> solvers = {"full"};
    if (every_block_closed(file)) solvers.push_back("analytic");
    double size = 0.0;
    for (const auto& joint : file.rough_positions()) size = std::max(size, joint.norm());
    const SweepRange range = range_for(c.name, file, size);
    for (const std::string& solver : solvers) {
      INFO("solver " << solver);
      const NamedSweep expected = sweep_by_name(file, solver, range);
      // Five poses at least assemble, so that the comparison is not empty.
      const auto assembled = std::count(expected.status.begin(), expected.status.end(), Status::converged);
      INFO(assembled << " of " << expected.status.size() << " poses assemble");
      REQUIRE(assembled >= 5);
      // Each body through every order of its joints, the others as written, with the tables as
      // written and reversed.
      for (int table_order = 0; table_order < 2; ++table_order) {
        const LinkageDescription tables = with_tables_in_order(text, table_order);
        for (std::size_t b = 0; b < tables.bodies.size(); ++b) {
          for (const std::vector<int>& order : permutations(tables.bodies[b].joints.size())) {
            LinkageDescription d = tables;
            reorder_body(d, b, order);
            const LinkageModel model(std::move(d));
            std::string written;
            for (int k : order) written += std::to_string(k);
            INFO("table order " << table_order << ", body " << tables.bodies[b].name << " in order " << written);
            require_same_poses(expected, sweep_by_name(model, solver, range), model.unknown_count(), size);
          }
        }
      }
    }
  }
}

TEST_CASE("Joint order: the skew pantograph's dyads, its closed form, and the file-order pairs that lose them", "[linkage-joint-order]") {
  const std::string text = text_of(pantograph_path());
  LinkageDescription d = parse_linkage_description(text, pantograph_path());
  // Both bars listed from their far end: the file-order pairs are A-D (O placed from it) and P-E.
  reorder_body(d, 0, {2, 1, 0});
  reorder_body(d, 1, {2, 1, 0});
  const LinkageModel chosen(d);
  const LinkageModel file_order(d, {});
  // 1. The pairs follow the structure: O and D (D a dyad from O and F), then A and E (E a dyad from
  //    A and F), in the order the body lists them.
  const auto pair_names = [&](const LinkageModel& model, std::size_t b) {
    const BodySpec& body = model.description().bodies[b];
    const auto pair = model.base_pairs()[b];
    return name_of(model, body.joints[static_cast<std::size_t>(pair[0])]) + "-" + name_of(model, body.joints[static_cast<std::size_t>(pair[1])]);
  };
  CHECK(pair_names(chosen, 0) == "D-O");
  CHECK(pair_names(chosen, 1) == "E-A");
  const std::vector<int> rounds = known_rounds(chosen);
  const auto round_of = [&](const char* name) { return rounds[static_cast<std::size_t>(chosen.description().joint_index(name))]; };
  CHECK(round_of("O") == 0);
  CHECK(round_of("G") == 0);
  CHECK(round_of("F") == 1);
  CHECK(round_of("D") == 2);
  CHECK(round_of("A") == 3);
  CHECK(round_of("E") == 4);
  CHECK(round_of("P") == 5);
  // 2. Every block in closed form: the crank, two dyads, two body points.
  CHECK(block_sizes(chosen) == std::multiset<std::size_t>{2, 2, 2, 2, 2});
  CHECK(every_block_closed(chosen));
  // 3. The pairs in the file's order (the rule before) tie D, A, E, P into Newton blocks.
  CHECK_FALSE(every_block_closed(file_order));
  CHECK(block_sizes(file_order) != block_sizes(chosen));
  // 4. The poses against the pantograph's closed form: F on its circle about G, and the tracer
  //    P - O = s (F - O) with s = 1 - 1/m, m = -e^(20 deg i) (the file's comment).
  LinkageSolverOptions options;
  options.solver = "analytic";
  const LinkageSolver linkage(chosen, options);
  const LinkageSweep sweep = linkage_sweep(linkage, 0.0, 360.0, 10.0);
  REQUIRE(sweep.status == Status::converged);
  const std::complex<double> m = -std::polar(1.0, 20.0 * deg), s = 1.0 - 1.0 / m;
  const Eigen::Vector2d O = chosen.rough_positions()[static_cast<std::size_t>(chosen.description().joint_index("O"))];
  const Eigen::Vector2d G = chosen.rough_positions()[static_cast<std::size_t>(chosen.description().joint_index("G"))];
  for (const LinkagePose& pose : sweep.poses) {
    INFO("crank " << pose.driver);
    const Eigen::Vector2d F = joint_at(chosen, pose.q, "F"), P = joint_at(chosen, pose.q, "P");
    const Eigen::Vector2d F_closed = G + 0.4 * Eigen::Vector2d(std::cos(pose.driver * deg), std::sin(pose.driver * deg));
    const std::complex<double> tracer = s * std::complex<double>(F.x() - O.x(), F.y() - O.y());
    // The bound: the closed-form check's own (10 ||J^-1||_2 (||Phi||_2 + n eps |q|)), times |s| for P.
    CHECK((F - F_closed).norm() <= pose.closed_form_bound);
    CHECK((P - O - Eigen::Vector2d(tracer.real(), tracer.imag())).norm() <= 2.0 * std::abs(s) * pose.closed_form_bound);
  }
}

TEST_CASE("Joint order: a body point named before a Newton block's joints stays out of the block", "[linkage-joint-order]") {
  const LinkageModel model(parse_linkage_description(stephenson_with_a2(), "stephenson-a2.toml"));
  // a (crank), c (a point of T1), d, e, f (6x6), then a2 a point of T2 from two of d, e, f.
  CHECK(block_sizes(model) == std::multiset<std::size_t>{2, 2, 6, 2});
  const std::vector<int> rounds = known_rounds(model);
  const auto round_of = [&](const char* name) { return rounds[static_cast<std::size_t>(model.description().joint_index(name))]; };
  CHECK(round_of("d") == 3);
  CHECK(round_of("e") == 3);
  CHECK(round_of("f") == 3);
  CHECK(round_of("a2") == 4);
  const BodySpec& T2 = model.description().bodies[1];
  const auto pair = model.base_pairs()[1];
  const std::set<std::string> chosen = {name_of(model, T2.joints[static_cast<std::size_t>(pair[0])]),
                                        name_of(model, T2.joints[static_cast<std::size_t>(pair[1])])};
  CHECK(chosen == std::set<std::string>{"d", "e"});
}
