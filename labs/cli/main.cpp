// numlab: the command-line program (docs/cli.md).
// Exit codes: 0 the method succeeded, 1 it ran but did not succeed, 2 bad usage or bad input.

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <stdexcept>
#include <utility>
#include <vector>

#include "commands/bench_command.hpp"
#include "cli/build_info.hpp"
#include "commands/common_options.hpp"
#include "commands/basins_command.hpp"
#include "commands/exercise_command.hpp"
#include "commands/exercise_grade.hpp"
#include "commands/fit_command.hpp"
#include "commands/labs_command.hpp"
#include "commands/mechanism_command.hpp"
#include "commands/models_command.hpp"
#include "commands/solve_linear.hpp"
#include "commands/solve_nonlinear.hpp"
#include "numlab/printable_text.hpp"
#include "output/files.hpp"

namespace {

// Without arguments numlab runs its main job non-interactively.
int run_main_job() {
  std::cout << "numlab: no sub-command, so running the main job: the Jansen leg lab.\n"
               "        (numlab --help lists the sub-commands; numlab labs lists the labs.)\n";
  return numlab::cli::run_lab("jansen", false, "out");
}

// A word (a run without spaces) longer than max_word bytes keeps its first bytes and says how long
// it was, so that a 100 kB argument quoted in a message still gives a short line. Cuts at a
// character boundary: the text is printable() output, so whole UTF-8 characters.
std::string shorten_long_words(const std::string& text, std::size_t max_word = 80) {
  std::string shortened;
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t space = std::min(text.find(' ', position), text.size());
    const std::size_t length = space - position;
    if (length <= max_word) {
      shortened.append(text, position, length);
    } else {
      std::size_t cut = position + max_word - 20;
      while (cut > position && (static_cast<unsigned char>(text[cut]) & 0xC0u) == 0x80u) --cut;
      shortened.append(text, position, cut - position);
      shortened += "...(" + std::to_string(length) + " bytes)";
    }
    if (space < text.size()) shortened += ' ';
    position = space + 1;
  }
  return shortened;
}

// The deepest sub-command given (solve linear: linear), or the program itself.
const CLI::App& deepest_command(const CLI::App& app) {
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  return *command;
}

// "numlab solve linear": the program and the sub-commands given.
std::string command_words(const CLI::App& app) {
  std::string words;
  for (const CLI::App* command = &deepest_command(app); command != nullptr; command = command->get_parent()) {
    words = (command->get_parent() == nullptr ? std::string("numlab") : command->get_name()) +
            (words.empty() ? "" : " ") + words;
  }
  return words;
}

// "a whole number" or "a number", as the option `name` of the deepest command expects.
std::string kind_of_number(const CLI::App& app, const std::string& name) {
  const CLI::Option* option = deepest_command(app).get_option_no_throw(name);
  const std::string type = option != nullptr ? option->get_type_name() : "";
  if (type.starts_with("UINT")) return "a whole number >= 0";
  return type.starts_with("INT") ? "a whole number" : "a number";
}

std::string quoted_words(const std::vector<std::string>& words) {
  std::string listed;
  for (const std::string& word : words) listed += (listed.empty() ? "'" : ", '") + word + "'";
  return listed;
}

// "{a,b,c}" -> "a, b, c"
std::string listed_set(std::string set) {
  if (set.size() >= 2 && set.front() == '{' && set.back() == '}') set = set.substr(1, set.size() - 2);
  std::string listed;
  for (const char c : set) listed += c == ',' ? std::string(", ") : std::string(1, c);
  return listed;
}

// `text` split at the first `marker` (before, after), or nothing when it has none. (Not std::regex:
// its matcher recurses per character, and a 100 kB argument overflows the stack.)
std::optional<std::pair<std::string, std::string>> split_at(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return std::nullopt;
  return std::pair{text.substr(0, at), text.substr(at + marker.size())};
}

// CLI11's validators: "NAME: Value V not in range A to B" (CLI::Range), "NAME: V not in {a,b}"
// (CLI::IsMember); numlab's own validators' messages pass as they are.
std::string validation_in_own_words(const std::string& text, const std::string& command) {
  const auto named = split_at(text, ": ");
  if (!named) return text;
  const auto& [name, rest] = *named;
  if (const auto range = split_at(rest, " not in range "); range && range->first.starts_with("Value ")) {
    const auto bounds = split_at(range->second, " to ");
    if (bounds) {
      return fmt::format("{} must be a whole number from {} to {}, got '{}'", name, bounds->first, bounds->second,
                         range->first.substr(6));
    }
  }
  const std::size_t set = rest.rfind(" not in {");
  if (set != std::string::npos && rest.ends_with('}')) {
    const std::string who = name.starts_with('-') ? name : command + ":";  // a flag, or a positional word
    return fmt::format("{} '{}' is not one of: {}", who, rest.substr(0, set), listed_set(rest.substr(set + 8)));
  }
  return text;
}

// CLI11's counts: "NAME: At Most 1 required but received 2", "NAME: 1 required TYPE missing".
std::string mismatch_in_own_words(const std::string& text, const std::string& command) {
  if (const auto most = split_at(text, ": At Most 1 required but received ")) {
    return fmt::format("{} is given {} times; give it once", most->first, most->second);
  }
  if (const auto named = split_at(text, ": "); named && named->second.find(" required ") != std::string::npos &&
                                               named->second.ends_with(" missing")) {
    return fmt::format("{} needs a value ({} --help says which)", named->first, command);
  }
  return text;
}

// A CLI11 parse error in numlab's words. CLI11's own phrasing ("At Most 1 required but received 2",
// "1 required TEXT:{...} missing", "The following arguments were not expected: json --format", which
// lists the words in reverse) is replaced case by case; a message numlab's validators wrote passes.
std::string parse_error_in_own_words(const CLI::ParseError& error, const CLI::App& app) {
  const std::string text = error.what();
  const std::string command = command_words(app);
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    const std::vector<std::string> extra = app.remaining(true);
    const bool flag_first = !extra.empty() && extra.front().starts_with('-') && command == "numlab";
    return fmt::format("unexpected {} {} for {} ({} --help lists what it takes{})",
                       extra.size() == 1 ? "argument" : "arguments", quoted_words(extra), command, command,
                       flag_first ? "; flags go after the command they are for" : "");
  }
  if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr) return validation_in_own_words(text, command);
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) return mismatch_in_own_words(text, command);
  if (dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
    if (const auto converted = split_at(text, "Could not convert: ")) {
      if (const auto value = split_at(converted->second, " = ")) {
        return fmt::format("{} must be {}, got '{}'", value->first, kind_of_number(app, value->first), value->second);
      }
    }
  }
  if (dynamic_cast<const CLI::ExcludesError*>(&error) != nullptr) return text + ": give one of them, not both";
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr && !text.starts_with("-")) {
    if (const auto word = split_at(text, " is required"); word && word->second.empty()) {
      return fmt::format("{} needs its {} argument ({} --help)", command, word->first, command);
    }
  }
  return text;
}

// Bad input: one short line on stderr, whatever bytes the message quotes from outside.
int bad_input(const std::string& message) {
  std::cerr << "numlab: error: " << shorten_long_words(numlab::printable(message)) << '\n';
  return numlab::cli::exit_bad_input;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace numlab::cli;
  CLI::App app{"numlab - a numerical-methods teaching toolkit: hand-written solvers, traced, checked against GSL"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", fmt::format("numlab {} (git commit {})", build_version(), build_commit()),
                       "Print numlab's version and the git commit it was built from, and exit");
  app.footer(fmt::format("Exit codes: {} success; {} the method ran but did not succeed (a status other than\n"
                         "converged, a failed check, stopped with q); {} bad usage or bad input (one line on\n"
                         "stderr says what was wrong).",
                         exit_success, exit_method_failed, exit_bad_input));
  CLI::App* solve = app.add_subcommand("solve", "Solve one problem with one method");
  solve->require_subcommand(0, 1);
  const SolveLinearCommand solve_linear(*solve);
  const SolveNonlinearCommand solve_nonlinear(*solve);
  const LabsCommand labs(app);
  const BenchCommand bench(app);
  const MechanismCommand mechanism(app);
  const FitCommand fit(app);
  const ExerciseCommand exercise(app);
  const ExerciseGradeCommand exercise_grade(*app.get_subcommand("exercise"));
  const BasinsCommand basins(app);
  const ModelsCommand models(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    return bad_input(parse_error_in_own_words(error, app));
  }

  const auto run_command = [&]() {
    if (solve_linear.selected()) return solve_linear.run();
    if (solve_nonlinear.selected()) return solve_nonlinear.run();
    if (solve->parsed()) throw std::invalid_argument("solve: say what to solve, e.g. numlab solve linear --help");
    if (labs.list_selected()) return labs.list();
    if (labs.lab_selected()) return labs.run();
    if (bench.selected()) return bench.run();
    if (mechanism.selected()) return mechanism.run();
    if (fit.selected()) return fit.run();
    if (exercise_grade.selected()) return exercise_grade.run();
    if (exercise.selected()) return exercise.run();
    if (basins.selected()) return basins.run();
    if (models.selected()) return models.run();
    return run_main_job();
  };
  try {
    const int code = run_command();
    check_standard_output();  // a result cut short by a full disk is not a success
    return code;
  } catch (const std::exception& error) {
    return bad_input(error.what());
  }
}
