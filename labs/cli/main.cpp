// numlab: the command-line program (docs/cli.md).
// Exit codes: 0 the method succeeded, 1 it ran but did not succeed, 2 bad usage or bad input.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <stdexcept>

#include "bench/bench_linear.hpp"
#include "cli/cli_common.hpp"
#include "commands/basins_command.hpp"
#include "commands/exercise_command.hpp"
#include "commands/fit_command.hpp"
#include "commands/labs_command.hpp"
#include "commands/mechanism_command.hpp"
#include "commands/models_command.hpp"
#include "commands/solve_linear.hpp"
#include "commands/solve_nonlinear.hpp"
#include "numlab/printable_text.hpp"

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
  CLI::App* solve = app.add_subcommand("solve", "Solve one problem with one method");
  solve->require_subcommand(0, 1);
  const SolveLinearCommand solve_linear(*solve);
  const SolveNonlinearCommand solve_nonlinear(*solve);
  const LabsCommand labs(app);
  const BenchCommand bench(app);
  const MechanismCommand mechanism(app);
  const FitCommand fit(app);
  const ExerciseCommand exercise(app);
  const BasinsCommand basins(app);
  const ModelsCommand models(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    return bad_input(error.what());
  }

  try {
    if (solve_linear.selected()) return solve_linear.run();
    if (solve_nonlinear.selected()) return solve_nonlinear.run();
    if (solve->parsed()) throw std::invalid_argument("solve: say what to solve, e.g. numlab solve linear --help");
    if (labs.list_selected()) return labs.list();
    if (labs.lab_selected()) return labs.run();
    if (bench.selected()) return bench.run();
    if (mechanism.selected()) return mechanism.run();
    if (fit.selected()) return fit.run();
    if (exercise.selected()) return exercise.run();
    if (basins.selected()) return basins.run();
    if (models.selected()) return models.run();
    return run_main_job();
  } catch (const StoppedByUser& stopped) {
    std::cerr << "numlab: " << stopped.what() << '\n';
    return exit_method_failed;
  } catch (const std::exception& error) {
    return bad_input(error.what());
  }
}
