#include "commands/labs_command.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <iostream>
#include <stdexcept>

#include "lessons/lab.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {
std::vector<std::string> lab_names() {
  std::vector<std::string> names;
  for (const Lab& lab : all_labs()) names.push_back(lab.name);
  return names;
}
}  // namespace

LabsCommand::LabsCommand(CLI::App& app) {
  list_ = app.add_subcommand("labs", "List the labs");
  lab_ = app.add_subcommand("lab", "Run one lab: explained steps, tables, and the files they write");
  lab_->add_option("name", name_, "Lab name (see `numlab labs`)")->required()->check(CLI::IsMember(lab_names()));
  add_common_options(*lab_, common_);
}

int LabsCommand::list() const {
  Table table({"name", "what it shows"});
  for (const Lab& lab : all_labs()) table.add_row({lab.name, lab.summary});
  table.print_within(std::cout, terminal_width);
  std::cout << "\nRun one with: numlab lab NAME [--step]\n";
  return exit_success;
}

int LabsCommand::run() const {
  const CommonOptions common = checked_common_options(common_, "lab");
  return run_lab(name_, common.step, common.out_dir);
}

int run_lab(const std::string& name, bool step, const std::string& out_dir) {
  for (const Lab& lab : all_labs()) {
    if (lab.name != name) continue;
    // The lab's folder first: a folder that cannot be made is bad input before any output.
    ensure_directory(out_dir + "/lab-" + lab.name);
    std::cout << fmt::format("numlab lab {}: {}\n", lab.name, lab.summary);
    if (step && isatty(STDIN_FILENO) != 0) std::cout << "(--step: Enter after each step goes on; q, Enter stops)\n";
    LabSession session(std::cout, step, out_dir + "/lab-" + lab.name, lab.name, lab.summary);
    int exit_code = lab.run(session);
    if (session.stopped()) {
      // q at a pause: the lab returned there; the report keeps the steps that ran.
      session.say(fmt::format("Stopped with q after step {}: the steps above are the ones that ran.",
                              session.steps_taken()));
      exit_code = exit_method_failed;
    }
    std::cout << "Report: " << session.finish() << " (steps, tables and figures in one page)\n";
    return exit_code;
  }
  throw std::invalid_argument("unknown lab '" + name + "' (see numlab labs)");
}

}  // namespace numlab::cli
