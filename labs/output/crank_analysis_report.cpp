// --analyse: the four-bar or slider-crank analysis (crank_analysis.hpp) as text or JSON.

#include <fmt/format.h>

#include <cmath>

#include "output/linkage_report.hpp"

namespace numlab::cli {

using namespace mechanisms;

namespace {

std::string toggle_text(const Toggle& t) {
  std::string text = fmt::format("crank {:.9f} deg ({}", t.crank_deg, t.what);
  if (std::isfinite(t.closed_form_deg)) {
    text += fmt::format("; closed form {:.9f}, difference {:.1e} deg", t.closed_form_deg,
                        std::abs(std::remainder(t.crank_deg - t.closed_form_deg, 360.0)));
  }
  return text + ")";
}

nlohmann::ordered_json toggles_json(const std::vector<Toggle>& toggles) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Toggle& t : toggles) {
    out.push_back({{"crank_deg", t.crank_deg}, {"closed_form_deg", number_or_null(t.closed_form_deg)}, {"what", t.what}});
  }
  return out;
}

}  // namespace

void print_crank_analysis(std::ostream& out, const LinkageModel& model, const CrankAnalysis& a, const std::string& file,
                          Format format) {
  const auto& d = model.description();
  const bool four_bar = a.kind == "four-bar";
  if (format == Format::json) {
    nlohmann::ordered_json json = {{"mechanism", d.name}, {"kind", a.kind.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(a.kind)}};
    if (a.kind.empty()) {
      json["not_analysed"] = a.not_analysed;
      out << json.dump(2) << '\n';
      return;
    }
    json["links"] = {{"crank", {{"name", a.crank_name}, {"length", a.crank}}},
                     {"coupler", {{"name", a.coupler_name}, {"length", a.coupler}}}};
    if (four_bar) {
      json["links"]["rocker"] = {{"name", a.rocker_name}, {"length", a.rocker}};
      json["links"]["ground"] = {{"length", a.ground}};
      json["grashof"] = {{"s", a.shortest}, {"l", a.longest}, {"p_plus_q", a.others}, {"grashof", a.grashof},
                         {"shortest", a.shortest_name}};
    } else {
      json["offset"] = a.ground;
    }
    json["classification"] = a.classification;
    json["output"] = a.output;
    json["crank_turns_fully"] = a.crank_turns_fully;
    json["driver_toggles"] = toggles_json(a.driver_toggles);
    json["output_toggles"] = toggles_json(a.output_toggles);
    json["alpha_deg"] = number_or_null(a.alpha_deg);
    json["time_ratio"] = number_or_null(a.time_ratio);
    json["time_ratio_closed_form"] = number_or_null(a.time_ratio_closed_form);
    json["brent_iterations"] = a.brent_iterations;
    out << json.dump(2) << '\n';
    return;
  }
  out << fmt::format("mechanism          {}{} ({})\n", d.name, d.title.empty() ? "" : ": " + d.title, file);
  if (a.kind.empty()) {
    out << a.not_analysed << '\n';
    return;
  }
  if (four_bar) {
    out << fmt::format("structure          four-bar: crank {} {:g}, coupler {} {:g}, rocker {} {:g}, ground {:g}\n", a.crank_name,
                       a.crank, a.coupler_name, a.coupler, a.rocker_name, a.rocker, a.ground)
        << fmt::format("grashof            s + l = {:g} + {:g} = {:g} {} p + q = {:g}: {}; the shortest link is the {}\n",
                       a.shortest, a.longest, a.shortest + a.longest, a.grashof ? "<=" : ">", a.others,
                       a.grashof ? "Grashof" : "not Grashof", a.shortest_name);
  } else {
    out << fmt::format("structure          slider-crank: crank {} {:g}, rod {} {:g}, offset {:g}\n", a.crank_name, a.crank,
                       a.coupler_name, a.coupler, a.ground);
  }
  out << fmt::format("classification     {}\n", a.classification)
      << fmt::format("output             {}\n", a.output);
  if (a.driver_toggles.empty()) out << "driver toggles     none: the crank turns fully\n";
  for (std::size_t k = 0; k < a.driver_toggles.size(); ++k) {
    out << (k == 0 ? "driver toggles     " : "                   ") << toggle_text(a.driver_toggles[k]) << '\n';
  }
  if (a.output_toggles.empty()) out << "output toggles     none: the output's velocity ratio keeps its sign\n";
  for (std::size_t k = 0; k < a.output_toggles.size(); ++k) {
    out << (k == 0 ? "output toggles     " : "                   ") << toggle_text(a.output_toggles[k]) << '\n';
  }
  if (std::isfinite(a.time_ratio)) {
    out << fmt::format("time ratio         {:.9f} = (180 + alpha) / (180 - alpha), alpha {:.9f} deg: the crank turns {:.6f} deg "
                       "one way between the toggles, {:.6f} the other",
                       a.time_ratio, a.alpha_deg, 180.0 + a.alpha_deg, 180.0 - a.alpha_deg);
    if (std::isfinite(a.time_ratio_closed_form)) out << fmt::format("; closed form {:.9f}", a.time_ratio_closed_form);
    out << '\n';
  } else {
    out << "time ratio         none: it needs a crank that turns fully and an output with two toggles\n";
  }
  out << fmt::format("root finding       Brent (GSL) on the output's velocity ratio in brackets from a 1-degree sweep (the "
                     "driver's: on |AQ| - (b +- c)), to 1e-10 rad; at most {} iterations\n",
                     a.brent_iterations);
}

}  // namespace numlab::cli
