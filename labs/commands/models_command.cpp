#include "commands/models_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "methods/data_dir.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace fs = std::filesystem;

ModelsCommand::ModelsCommand(CLI::App& app) {
  command_ = app.add_subcommand("models", "List the linkage description files shipped with numlab");
  add_common_options(*command_, common_);
}

namespace {

struct ModelEntry {
  std::string name, title, file, driver, blocks;
  int joints = 0, unknowns = 0, newton_blocks = 0;
};

ModelEntry describe(const fs::path& file) {
  const mechanisms::LinkageModel model(mechanisms::read_linkage_description(file.string()));
  const auto blocks = mechanisms::linkage_blocks(model);
  ModelEntry entry{file.stem().string(), model.description().title, file.string(), "", "", 0, model.unknown_count(), 0};
  entry.joints = static_cast<int>(model.description().joints.size());
  constexpr const char* kinds_of_driver[] = {"crank", "slider", "actuator", "motor"};  // DriverKind's order
  entry.driver = kinds_of_driver[static_cast<int>(model.description().driver.kind)];
  if (const auto& second = model.description().second_driver) entry.driver += std::string("+") + kinds_of_driver[static_cast<int>(second->kind)];
  std::vector<std::string> kinds;
  for (const auto& block : blocks) {
    if (!block.closed_form()) ++entry.newton_blocks;
    kinds.push_back(block.kind == mechanisms::BlockKind::slot_pivot ? "slotted link"
                    : block.closed_form()                             ? (block.dyad() ? "dyad" : "explicit")
                                        : fmt::format("{}x{} Newton", block.rows_and_columns.unknowns.size(),
                                                      block.rows_and_columns.unknowns.size()));
  }
  entry.blocks = fmt::format("{}", fmt::join(kinds, ", "));
  return entry;
}

}  // namespace

int ModelsCommand::run() const {
  const CommonOptions common = checked_common_options(common_, "models");
  const std::string dir = models_dir();
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(dir)) {
    if (item.is_regular_file() && item.path().extension() == ".toml") files.push_back(item.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<ModelEntry> entries;
  for (const auto& file : files) entries.push_back(describe(file));
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"folder", dir}, {"models", nlohmann::ordered_json::array()}};
    for (const auto& e : entries) {
      out["models"].push_back({{"name", e.name}, {"title", e.title}, {"file", e.file}, {"joints", e.joints},
                               {"unknowns", e.unknowns}, {"driver", e.driver}, {"blocks", e.blocks},
                               {"newton_blocks", e.newton_blocks}});
    }
    std::cout << out.dump(2) << '\n';
    return exit_success;
  }
  Table table({"name", "joints", "unknowns", "driver", "title; blocks in order"});
  for (const auto& e : entries) {
    table.add_row({e.name, std::to_string(e.joints), std::to_string(e.unknowns), e.driver, e.title + "\n" + e.blocks});
  }
  table.print_within(std::cout, terminal_width);
  const std::string closing = fmt::format(
      "{} models in {}; run one with: numlab mechanism NAME --crank 30 (the built-in jansen, jansen10 and mustang "
      "are the seeds' hand-written models; the files are jansen.toml and mustang.toml: numlab mechanism "
      "jansen.toml ...)",
      entries.size(), dir);
  for (const std::string& line : wrap_words(closing, terminal_width)) std::cout << line << '\n';
  return exit_success;
}

}  // namespace numlab::cli
