#pragma once
// A failure a student can replay (docs/exercises.md, "Replaying a failure"). `exercise check --out
// DIR` saves each failing check's requests as DIR/replay/NN-CHECK.jsonl, one JSON object a line:
//   {"check", "inputs", "request", "expected", "property", "your_reply" | "your_error"}
// "request" is the line numlab sent (pipe it to the program: jq -c .request FILE), "expected" is
// numlab's reply beside it (null when no single reply is right; "property" then says what is
// checked), "your_reply" what the program answered. `exercise replay FILE -- COMMAND` runs the
// same check again against COMMAND and shows the three side by side.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exercises/checker.hpp"
#include "exercises/exercise.hpp"

namespace numlab::exercises {

// "03-gepp-on-hilbert-10-kappa-3-5e13-is-backward-stable.jsonl": the check's 1-based place in the
// battery and its name in lower case, words joined by '-', cut at a word to at most 60 characters.
std::string replay_file_name(int place, const std::string& check_name);

// The file's text: one line per request of the check, each ending in '\n'. With a variant, each line
// also has "variant": its ID (a replay rebuilds the check of that variant).
std::string replay_lines(const CheckResult& result, const Variant& variant = Variant());

// What a replay file holds: the exercise and check it came from, and the requests in order.
struct ReplayFile {
  std::string exercise;
  std::string check;
  std::vector<nlohmann::json> requests;
  Variant variant;  // the lines' "variant", if they have one
};

// Reads a replay file; std::invalid_argument with one line ("exercise replay: FILE line 3: ...")
// when it cannot be read or is not a replay file.
ReplayFile read_replay_file(const std::string& path);

// The check of `exercise` named `name` in the battery of `variant`; std::invalid_argument when none is.
Check find_check(const Exercise& exercise, const std::string& name, const Variant& variant = Variant());

// What `exercise replay` prints: each request (cut to a line), the program's reply and numlab's
// expectation side by side, then the verdict; `mismatch` notes where the requests sent now differ
// from the file's ("" when they agree).
std::string replay_text(const CheckResult& result, const std::string& mismatch);

// Where the requests of `result` first differ from the file's, or "" when every request both have
// is the same (a check that now passes may send more requests than the failure did).
std::string requests_mismatch(const ReplayFile& file, const CheckResult& result);

}  // namespace numlab::exercises
