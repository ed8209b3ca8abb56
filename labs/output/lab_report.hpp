#pragma once
// A lab's report.html: its steps, paragraphs, tables, printed output and figures in the order the
// lab produced them, in one self-contained file (SVG figures inlined, PNG figures as data URIs,
// styles inline), so it reads offline in any browser.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "output/report_style.hpp"
#include "output/table.hpp"

namespace numlab::cli {

class LabReport {
 public:
  LabReport(std::string title, std::string summary) : title_(std::move(title)), summary_(std::move(summary)) {}

  void add_step(int number, const std::string& title);
  void add_paragraph(const std::string& text);
  void add_table(const Table& table, const std::string& saved_as);
  void add_preformatted(const std::string& text);
  // Reads the figure file now (it must exist) and embeds it.
  void add_figure(const std::string& path, const std::string& caption);
  // A traced solve the reader steps through in the browser (html/stepper.js): `kind` (gepp, sweeps,
  // newton) says how a record is drawn; `data` holds "trace" (the records, as --trace --format json
  // prints them), "lines" (the text --trace prints for each), "header", and for gepp "start", [A | b].
  // The page embeds it as JSON; without scripts the stepper stays hidden and the printed trace reads.
  void add_stepper(const std::string& kind, const std::string& caption, const nlohmann::ordered_json& data);

  // The figure files embedded so far, as given to add_figure.
  const std::vector<std::string>& figures() const { return figures_; }

  // The whole document.
  std::string html() const;

 private:
  std::string title_;
  std::string summary_;
  std::string body_;
  std::vector<std::string> figures_;
  bool has_steppers_ = false;
};

}  // namespace numlab::cli
