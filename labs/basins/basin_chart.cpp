#include "basins/basin_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numbers>

#include "basins/basin_sentences.hpp"

namespace numlab::basins {

namespace {

struct Rgb {
  int r, g, b;
};

Rgb from_hex(unsigned hex) { return {int(hex >> 16 & 0xff), int(hex >> 8 & 0xff), int(hex & 0xff)}; }
std::string hex_of(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

// Modes take these in the order of their numbers among the modes reached.
constexpr std::array<unsigned, 16> mode_palette = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x17becf,
                                                   0xe377c2, 0x637939, 0x393b79, 0x8c6d31, 0x843c39, 0x7b4173,
                                                   0x3182bd, 0x31a354, 0xe6550d, 0x756bb1};
constexpr unsigned unknown_colour = 0xffff00;  // a root of no known mode: yellow

struct FailureStyle {
  Status status;
  unsigned colour;
};
constexpr std::array<FailureStyle, 5> failure_styles = {{{Status::diverged, 0x000000},
                                                         {Status::singular, 0xff00ff},
                                                         {Status::max_iterations, 0x6e6e6e},
                                                         {Status::non_finite, 0x8b4513},
                                                         {Status::no_progress, 0xb8a000}}};

unsigned failure_colour(Status status) {
  for (const auto& style : failure_styles) {
    if (style.status == status) return style.colour;
  }
  return failure_styles.back().colour;
}

// The colour of each mode: palette entries in the order of the modes reached.
std::vector<Rgb> mode_colours(const BasinTally& counts) {
  std::vector<Rgb> colours(counts.per_mode.size(), from_hex(mode_palette[0]));
  std::size_t next = 0;
  for (std::size_t mode = 0; mode < counts.per_mode.size(); ++mode) {
    if (counts.per_mode[mode] > 0) colours[mode] = from_hex(mode_palette[next++ % mode_palette.size()]);
  }
  return colours;
}

// Converged points: the mode's colour moved towards white by up to 70% as iterations go from the
// fewest to the most any converged point took.
struct Shading {
  int fewest = 0, most = 1;
  Rgb apply(Rgb c, int iterations) const {
    const double t = most > fewest ? 0.7 * (iterations - fewest) / double(most - fewest) : 0.0;
    const auto lift = [t](int v) { return int(v + (255 - v) * t + 0.5); };
    return {lift(c.r), lift(c.g), lift(c.b)};
  }
};

Shading shading_of(const nonlinear::BasinMap& map) {
  Shading shading{1 << 30, 0};
  for (const auto& p : map.points) {
    if (p.status != Status::converged) continue;
    shading.fewest = std::min<int>(shading.fewest, p.iterations);
    shading.most = std::max<int>(shading.most, p.iterations);
  }
  if (shading.fewest > shading.most) shading = {0, 1};
  return shading;
}

Rgb pixel(const nonlinear::BasinPoint& p, const std::vector<Rgb>& modes, const Shading& shading) {
  if (p.status != Status::converged) return from_hex(failure_colour(p.status));
  if (p.mode < 0 || p.mode >= static_cast<int>(modes.size())) return from_hex(unknown_colour);
  return shading.apply(modes[static_cast<std::size_t>(p.mode)], p.iterations);
}

// A legend's share: the percentage, or the count when it would round to 0.0%.
std::string share_of(int count, int total) {
  if (1000LL * count >= total) return percent(count, total);
  return count == 1 ? "1 start" : fmt::format("{} starts", count);
}

// Text inside a gnuplot single-quoted string: a quote is written twice.
std::string quoted(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out;
}

}  // namespace

std::string failure_name(Status status) {
  switch (status) {
    case Status::max_iterations: return "max iterations";
    case Status::non_finite: return "non-finite";
    case Status::no_progress: return "no progress";
    default: return std::string(to_string(status));
  }
}

std::string basin_csv(const BasinRun& run) {
  const BasinTally counts = tally(run.map, static_cast<int>(run.mode_labels.size()));
  const auto colours = mode_colours(counts);
  const Shading shading = shading_of(run.map);
  std::string csv = "i,j,u,v,status,mode,iterations,r,g,b\n";
  csv.reserve(run.map.points.size() * 56);
  const auto& s = run.map.slice;
  for (int j = 0; j < s.rows; ++j) {
    for (int i = 0; i < s.columns; ++i) {
      const auto& p = run.map.at(i, j);
      const Rgb c = pixel(p, colours, shading);
      fmt::format_to(std::back_inserter(csv), "{},{},{:.9g},{:.9g},{},{},{},{},{},{}\n", i, j, s.u(i), s.v(j),
                     to_string(p.status), p.mode, p.iterations, c.r, c.g, c.b);
    }
  }
  return csv;
}

void draw_basin_chart(const cli::ChartFiles& files, const BasinRun& run, const std::string& title) {
  const BasinTally counts = tally(run.map, static_cast<int>(run.mode_labels.size()));
  const auto colours = mode_colours(counts);
  const auto& s = run.map.slice;
  const double du = (s.u_max - s.u_min) / (s.columns - 1) / 2, dv = (s.v_max - s.v_min) / (s.rows - 1) / 2;
  std::string script = cli::gnuplot_output_lines(files, 1060, 760);
  script += "set datafile separator ','\nset key outside right top box opaque spacing 1.2 width 1\n";
  script += fmt::format("set xrange [{:.9g}:{:.9g}]\nset yrange [{:.9g}:{:.9g}]\nset size ratio -1\n",
                        s.u_min - du, s.u_max + du, s.v_min - dv, s.v_max + dv);
  script += fmt::format("set xlabel '{}'\nset ylabel '{}'\nset title '{}'\nset tics out\n", quoted(run.u_name), quoted(run.v_name), quoted(title));
  // Marks: the solution and the seed's estimates.
  script += "$marks << EOD\n";
  for (const SliceMark& mark : run.marks) script += fmt::format("{:.9g},{:.9g}\n", mark.u, mark.v);
  script += "EOD\n";
  std::vector<std::string> plots = {fmt::format("'{}' using 3:4:8:9:10 every ::1 with rgbimage notitle", files.data)};
  for (std::size_t mode = 0; mode < counts.per_mode.size(); ++mode) {
    if (counts.per_mode[mode] == 0) continue;
    plots.push_back(fmt::format("keyentry with boxes fs solid 1.0 noborder lc rgb '{}' title '{} ({})'", hex_of(colours[mode]),
                                quoted(run.mode_labels[mode]), share_of(counts.per_mode[mode], counts.total)));
  }
  const auto add_flat = [&](int count, unsigned colour, const std::string& name) {
    if (count > 0) {
      plots.push_back(fmt::format("keyentry with boxes fs solid 1.0 noborder lc rgb '{}' title '{} ({})'",
                                  hex_of(from_hex(colour)), name, share_of(count, counts.total)));
    }
  };
  add_flat(counts.unknown, unknown_colour, "root of no known mode");
  add_flat(counts.diverged, failure_colour(Status::diverged), "diverged");
  add_flat(counts.singular, failure_colour(Status::singular), "singular");
  add_flat(counts.max_iterations, failure_colour(Status::max_iterations), "max iterations");
  add_flat(counts.non_finite, failure_colour(Status::non_finite), "non-finite");
  add_flat(counts.no_progress, failure_colour(Status::no_progress), "no progress");
  if (plots.size() > 1) {
    const Rgb first = colours[static_cast<std::size_t>(std::find_if(counts.per_mode.begin(), counts.per_mode.end(),
                                                                    [](int n) { return n > 0; }) - counts.per_mode.begin()) %
                              colours.size()];
    plots.push_back(fmt::format("keyentry with boxes fs solid 1.0 noborder lc rgb '{}' title 'lighter: more iterations'",
                                hex_of(Shading{0, 1}.apply(first, 1))));
  }
  if (run.toggle_lines) {
    const char* style = "with lines lw 2 dt 2 lc rgb 'black'";
    plots.push_back(fmt::format("x {} title 'toggle: theta3 - theta4 = k pi (J singular)'", style));
    plots.push_back(fmt::format("x + pi {} notitle, x - pi {} notitle", style, style));
  }
  // Each mark: a white filled symbol under a black outline (the outline names it in the key).
  const std::array<std::pair<int, int>, 2> symbols = {{{7, 6}, {9, 8}}};  // circle, triangle
  for (std::size_t k = 0; k < run.marks.size(); ++k) {
    const auto [filled, outline] = symbols[std::min<std::size_t>(k, 1)];
    plots.push_back(fmt::format("$marks every ::{0}::{0} using 1:2 with points pt {1} ps 1.7 lc rgb 'white' notitle", k, filled));
    plots.push_back(fmt::format("$marks every ::{0}::{0} using 1:2 with points pt {1} ps 1.7 lw 2 lc rgb 'black' title '{2}'",
                                k, outline, quoted(run.marks[k].label)));
  }
  script += "plot ";
  for (std::size_t k = 0; k < plots.size(); ++k) script += (k > 0 ? ", \\\n     " : "") + plots[k];
  script += "\n";
  cli::draw_chart(files, basin_csv(run), script);
}

}  // namespace numlab::basins
