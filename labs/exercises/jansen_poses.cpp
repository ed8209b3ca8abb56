#include "exercises/jansen_poses.hpp"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::exercises {

namespace {
mechanisms::JansenJoints closed_form_joints(double crank_angle, const mechanisms::JansenLeg& leg) {
  const auto joints = leg.closed_form_joints(crank_angle);
  if (!joints) throw std::logic_error("the Jansen leg's closed form failed (it assembles at every crank angle)");
  return *joints;
}

// The closed form on the seed's branch at every quarter degree: no dyad fails, the rigid triangles
// keep one orientation, and no joint jumps between neighbouring angles (a branch change).
bool assembles_over_cycle(const mechanisms::JansenLeg& leg) {
  std::optional<mechanisms::JansenJoints> last;
  int orientation = 0;
  for (int quarter = 0; quarter <= 4 * 360; ++quarter) {
    const auto joints = leg.closed_form_joints(quarter * 0.25 * degrees);
    if (!joints) return false;
    const int now = mechanisms::JansenLeg::triangle_orientation(*joints);
    if (orientation != 0 && now != orientation) return false;
    orientation = now;
    if (last) {
      for (std::size_t j = 0; j < joints->size(); ++j) {
        if (((*joints)[j] - (*last)[j]).norm() > 2.0) return false;  // a quarter degree moves a joint < 0.2
      }
    }
    last = joints;
  }
  return true;
}
}  // namespace

mechanisms::JansenAngles jansen_closed_form_angles(double crank_angle, const mechanisms::JansenLeg& leg) {
  return mechanisms::JansenLeg::angles_of(closed_form_joints(crank_angle, leg), mechanisms::JansenClosure::seed_estimates());
}

Eigen::VectorXd jansen10_closed_form_angles(double crank_angle, const mechanisms::JansenLeg& leg) {
  using mechanisms::JansenModel;
  return mechanisms::jansen_angles_of(JansenModel::ten_equations, closed_form_joints(crank_angle, leg),
                                      mechanisms::jansen_seed_estimates(JansenModel::ten_equations, leg));
}

double jansen_links_sum(const mechanisms::JansenLengths& L) {
  return L.crank + L.l1 + L.l2 + L.l3 + L.l4 + L.l5 + L.l6 + L.l7 + L.l8 + L.a + L.b;
}

LinkLengths JansenVariant::named() const {
  const mechanisms::JansenLengths& L = links;
  LinkLengths list = {{"crank", L.crank}, {"l1", L.l1}, {"l2", L.l2}, {"l3", L.l3}, {"l4", L.l4}, {"l5", L.l5},
                      {"l6", L.l6},       {"l7", L.l7}, {"l8", L.l8}, {"a", L.a},   {"b", L.b}};
  if (with_foot) list.insert(list.end(), {{"l9", foot.l9}, {"l10", foot.l10}});
  return list;
}

void JansenVariant::add_to(nlohmann::json& request) const {
  if (varied) request["lengths"] = lengths_json(named());
}

namespace {
JansenVariant jansen_from(const LinkLengths& list, bool with_foot) {
  JansenVariant v;
  v.with_foot = with_foot;
  mechanisms::JansenLengths& L = v.links;
  for (auto [name, field] : {std::pair{"crank", &L.crank}, {"l1", &L.l1}, {"l2", &L.l2}, {"l3", &L.l3}, {"l4", &L.l4},
                             {"l5", &L.l5}, {"l6", &L.l6}, {"l7", &L.l7}, {"l8", &L.l8}, {"a", &L.a}, {"b", &L.b}}) {
    *field = length_named(list, name);
  }
  if (with_foot) {
    v.foot.l9 = length_named(list, "l9");
    v.foot.l10 = length_named(list, "l10");
  }
  return v;
}
}  // namespace

JansenVariant jansen_variant(const Variant& variant, bool with_foot,
                             const std::function<bool(const mechanisms::JansenLeg&)>& valid) {
  const JansenVariant nominal{{}, {}, false, with_foot};
  const LinkLengths drawn = variant_lengths(variant, 7, nominal.named(), [&](const LinkLengths& list) {
    const mechanisms::JansenLeg leg = jansen_from(list, with_foot).leg();
    return assembles_over_cycle(leg) && (!valid || valid(leg));
  });
  JansenVariant chosen = jansen_from(drawn, with_foot);
  chosen.varied = variant.active();
  return chosen;
}

std::optional<std::string> jansen_seed_lengths_used(const Eigen::VectorXd& f, const Eigen::VectorXd& seed_f,
                                                    const JansenVariant& lengths, double tolerance) {
  if (!lengths.varied || (f - seed_f).cwiseAbs().maxCoeff() > tolerance) return std::nullopt;
  return fmt::format("your f is the closure with seed 000's lengths (the task's constants), to {:.3g}: your variant's "
                     "lengths are other ones ({}); read them from the request's \"lengths\"",
                     tolerance, lengths_text(lengths.named()));
}

std::string jansen_lengths_task_text(const JansenVariant& lengths) {
  if (!lengths.varied) return "";
  return fmt::format("Your leg's lengths are not seed 000's: each is within 3% of it, and every request carries them "
                     "as `lengths` (use those, not the constants above): {}.\n",
                     lengths_text(lengths.named()));
}

std::string jansen_angle_name(int index) { return "theta" + std::to_string(index + 1); }

}  // namespace numlab::exercises
