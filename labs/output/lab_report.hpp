#pragma once
// A lab's report.html: its steps, paragraphs, tables, printed output and figures in the order the
// lab produced them, in one self-contained file (SVG figures inlined, PNG figures as data URIs,
// styles inline), so it reads offline in any browser.

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

  // The figure files embedded so far, as given to add_figure.
  const std::vector<std::string>& figures() const { return figures_; }

  // The whole document.
  std::string html() const;

 private:
  std::string title_;
  std::string summary_;
  std::string body_;
  std::vector<std::string> figures_;
};

}  // namespace numlab::cli
