// --analyse: the four-bar or slider-crank analysis, or a crank-driven mechanism's output toggles and
// time ratio (crank_analysis.hpp), as text or JSON.

#include <fmt/format.h>

#include <cmath>

#include "output/linkage_report.hpp"

namespace numlab::cli {

using namespace mechanisms;

namespace {

std::string toggle_text(const Toggle& t, const CrankAnalysis& a) {
  std::string text = fmt::format("crank {:.9f} deg ({}", t.crank_deg, t.what);
  if (std::isfinite(t.output_value)) text += fmt::format("; {} at {:.9g}{}", a.output, t.output_value, a.output_is_angle ? " deg" : "");
  if (std::isfinite(t.closed_form_deg)) {
    text += fmt::format("; closed form {:.9f}, difference {:.1e} deg", t.closed_form_deg,
                        std::abs(std::remainder(t.crank_deg - t.closed_form_deg, 360.0)));
  }
  return text + ")";
}

nlohmann::ordered_json toggles_json(const std::vector<Toggle>& toggles) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Toggle& t : toggles) {
    out.push_back({{"crank_deg", t.crank_deg}, {"closed_form_deg", number_or_null(t.closed_form_deg)}, {"what", t.what},
                   {"output_value", number_or_null(t.output_value)}});
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
    if (!a.not_analysed.empty()) json["not_analysed"] = a.not_analysed;
    if (a.kind.empty()) {
      out << json.dump(2) << '\n';
      return;
    }
    json["links"] = {{"crank", {{"name", a.crank_name}, {"length", a.crank}}}};
    if (a.kind != "crank-driven") json["links"]["coupler"] = {{"name", a.coupler_name}, {"length", a.coupler}};
    if (four_bar) {
      json["links"]["rocker"] = {{"name", a.rocker_name}, {"length", a.rocker}};
      json["links"]["ground"] = {{"length", a.ground}};
      json["grashof"] = {{"s", a.shortest}, {"l", a.longest}, {"p_plus_q", a.others}, {"grashof", a.grashof},
                         {"shortest", a.shortest_name}};
    } else if (a.kind == "slider-crank") {
      json["offset"] = a.ground;
    }
    json["classification"] = a.classification;
    json["output"] = a.output;
    json["crank_turns_fully"] = a.crank_turns_fully;
    json["driver_toggles"] = toggles_json(a.driver_toggles);
    json["output_toggles"] = toggles_json(a.output_toggles);
    json["alpha_deg"] = number_or_null(a.alpha_deg);
    json["slow_stroke_deg"] = number_or_null(a.slow_stroke_deg);
    json["quick_stroke_deg"] = number_or_null(a.quick_stroke_deg);
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
  } else if (a.kind == "slider-crank") {
    out << fmt::format("structure          slider-crank: crank {} {:g}, rod {} {:g}, offset {:g}\n", a.crank_name, a.crank,
                       a.coupler_name, a.coupler, a.ground);
  } else {
    out << fmt::format("structure          crank-driven: crank link \"{}\" {:g}; {} (so no classification and no closed forms: the "
                       "output's toggles from its velocity ratio alone)\n",
                       a.crank_name, a.crank, a.not_analysed);
  }
  out << fmt::format("classification     {}\n", a.classification)
      << fmt::format("output             {}\n", a.output);
  if (a.driver_toggles.empty() && a.kind != "crank-driven") out << "driver toggles     none: the crank turns fully\n";
  for (std::size_t k = 0; k < a.driver_toggles.size(); ++k) {
    out << (k == 0 ? "driver toggles     " : "                   ") << toggle_text(a.driver_toggles[k], a) << '\n';
  }
  if (a.output_toggles.empty()) out << "output toggles     none: the output's velocity ratio keeps its sign\n";
  for (std::size_t k = 0; k < a.output_toggles.size(); ++k) {
    out << (k == 0 ? "output toggles     " : "                   ") << toggle_text(a.output_toggles[k], a) << '\n';
  }
  if (std::isfinite(a.time_ratio)) {
    out << fmt::format("time ratio         {:.9f} = slow / quick = (180 + alpha) / (180 - alpha), alpha {:.9f} deg: the slow "
                       "stroke takes {:.6f} deg of crank (from crank {:.6f}), the quick stroke {:.6f}",
                       a.time_ratio, a.alpha_deg, a.slow_stroke_deg,
                       a.output_toggles[static_cast<std::size_t>(a.slow_stroke_start)].crank_deg, a.quick_stroke_deg);
    if (std::isfinite(a.time_ratio_closed_form)) out << fmt::format("; closed form {:.9f}", a.time_ratio_closed_form);
    out << '\n';
  } else {
    out << "time ratio         none: it needs a crank that turns fully and an output with two toggles\n";
  }
  out << fmt::format("root finding       Brent (GSL) on the output's velocity ratio in brackets from a 1-degree sweep{}, "
                     "to 1e-10 rad; at most {} iterations\n",
                     four_bar ? " (the driver's: on |AQ| - (b +- c), a bracket per half-turn)"
                     : a.kind == "slider-crank" ? " (the driver's: on |e - r sin| - l, a bracket per half-turn)" : "",
                     a.brent_iterations);
}

}  // namespace numlab::cli
