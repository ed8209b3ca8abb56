#pragma once
// An exercise of `numlab exercise` (../../docs/exercises.md): the task a student is given, the
// starter stubs, and the battery of checks run against the student's program.
//
// A check talks to the student's program only through a Session (session.hpp): it sends requests,
// reads the replies with reply_fields.hpp, compares them with an independent reference (GSL, Eigen,
// numlab's own steppers, a closed form, NIST) and returns a Verdict.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "exercises/diagnosis.hpp"
#include "exercises/trace_comparison.hpp"
#include "exercises/variant.hpp"

namespace numlab::exercises {

class Session;

// The time one reference takes per request, shown beside the student's ("speed is informative,
// never a failure").
struct ReferenceTime {
  std::string name;            // "numlab GEPP", "GSL LU", ...
  double seconds_per_request;  // median over the check's requests
};

// What a check concluded from the replies.
struct Verdict {
  bool passed = false;
  // On failure: the quantity, the tolerance and the reference, e.g. "x differs from GSL LU by
  // 3.1e-2 (relative), allowed 1.2e-12 (kappa*eps*10)"; for a trace, the first step that departs.
  std::string message;
  // A generic hint: a family of mistakes that fits the symptom ("" when none fits), shown after the
  // message only when no detector fired (diagnosis.hpp).
  std::string hint;
  std::vector<ReferenceTime> references;
  // The most specific detector that fired on this failure, with its evidence; it replaces the hint.
  std::optional<Diagnosis> diagnosis;
  // A failing trace check's two traces, step by step, and where they part (trace_comparison.hpp).
  std::optional<TraceComparison> trace{};

  static Verdict pass(std::vector<ReferenceTime> references = {}) {
    return Verdict{true, "", "", std::move(references), std::nullopt};
  }
  static Verdict fail(std::string message, std::string hint = "", std::vector<ReferenceTime> references = {}) {
    return Verdict{false, std::move(message), std::move(hint), std::move(references), std::nullopt};
  }
  // A failure a detector explained: the hint is kept only for when `diagnosis` is empty.
  static Verdict fail(std::string message, std::optional<Diagnosis> diagnosis, std::string hint = "",
                      std::vector<ReferenceTime> references = {}) {
    return Verdict{false, std::move(message), std::move(hint), std::move(references), std::move(diagnosis)};
  }
};

struct Check {
  std::string name;  // states the property checked, e.g. "GEPP solves a random 50x50 system to ..."
  int task_id = 1;   // the numbered task of TASK.md this check belongs to (Exercism v3 task_id)
  // Runs the check. Throws ChildFailure or ReplyError (session.hpp, reply_fields.hpp) when the
  // program crashed, hung, or replied with something that is not a reply: the check is then an
  // `error`, not a `fail`.
  std::function<Verdict(Session&)> run;
};

// The method stub each starter leaves for the student, in each language. Each is the body of the
// function that handles one request; as generated it reports "not implemented".
struct Stubs {
  std::string python;  // body of `def solve(request):` (numpy imported as np)
  std::string cpp;     // body of `nlohmann::json solve(const nlohmann::json& request)`
  std::string octave;  // body of `function reply = solve(request)` (request from jsondecode)
};

struct Exercise {
  std::string name;     // "gepp"
  std::string summary;  // one line for `exercise list`
  // The task in Markdown: what to write, the request and reply fields, the exact equations, the
  // numbered tasks (task_id), and hints. `exercise show` prints it; `exercise init` saves TASK.md.
  // An exercise's task is the file tasks/NAME.md, embedded at build time (task_texts.hpp).
  std::string task;
  Stubs stubs;
  // The checks; every random input drawn from `variant` (variant.hpp: without an ID, the same requests
  // as always).
  std::function<std::vector<Check>(const Variant&)> battery;
  // What `check` and `grade` need beyond NAME, in the starter's check command: {"--model", "four-bar"}
  // for the linkage exercise (linkage_exercise.hpp); empty for the others.
  std::vector<std::string> arguments{};
  // What TASK.md's "Your variant" says beyond the ID, e.g. a linkage variant's link lengths (""
  // or unset: nothing more).
  std::function<std::string(const Variant&)> variant_task{};
  // The whole task of a variant, where the variant changes numbers the task itself states (the
  // linkage exercise's equations, written with the variant's lengths); unset: `task`.
  std::function<std::string(const Variant&)> varied_task{};
};

// Every exercise, in the order `exercise list` shows them.
const std::vector<Exercise>& all_exercises();

// The exercise called `name`; throws std::invalid_argument naming the known ones otherwise.
const Exercise& find_exercise(const std::string& name);

}  // namespace numlab::exercises
