#include "output/step_pause.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <iostream>
#include <string>

namespace numlab::cli {

namespace {

bool stop_answer(std::string line) {
  line.erase(std::remove_if(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c) != 0; }), line.end());
  return line == "q" || line == "Q";
}

}  // namespace

StepControl StepPause::after_step() {
  static bool noted = false;  // the note goes out once per run, whichever pause comes first
  if (stopped_) return StepControl::stop;
  if (!enabled_) return StepControl::proceed;
  if (isatty(STDIN_FILENO) == 0) {
    if (!noted) std::cerr << "numlab: note: --step pauses only when stdin is a terminal; it is not, so the run goes on\n";
    noted = true;
    return StepControl::proceed;
  }
  std::cerr << "  -- Enter: next step; q, Enter: stop here --" << std::flush;
  const auto begin = std::chrono::steady_clock::now();
  std::string line;
  const bool answered = static_cast<bool>(std::getline(std::cin, line));
  seconds_waited_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  stopped_ = !answered || stop_answer(line);
  return stopped_ ? StepControl::stop : StepControl::proceed;
}

}  // namespace numlab::cli
