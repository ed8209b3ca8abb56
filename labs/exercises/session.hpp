#pragma once
// How a check talks to the student's program: one JSON request out, one JSON reply back
// (docs/exercises.md, "The protocol"). The real session runs the program as a sandboxed child
// (child_session.hpp); tests may answer in-process (function_session.hpp).

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "exercises/library_calls.hpp"

namespace numlab::exercises {

// The program did not give a reply: it crashed, hung past the time limit, printed something that
// is not a JSON object, replied to another id, or exited. The check concerned is an `error`.
class ChildFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The program replied {"id": ..., "error": "..."}: its own code raised (the starters' stubs say
// "not implemented" this way). The check concerned fails with that message.
class StudentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What numlab expects of the reply to the request just sent, kept in the replay file of a failing
// check (docs/exercises.md, "Replaying a failure"). A check may say it after each ask(); a request
// without one is shown with the check's name as the property.
struct Expectation {
  std::string inputs;    // what the request holds, so it can be made again by hand: "random 8x8, seed 2"
  nlohmann::json reply;  // numlab's reply (its fields), or null when no single reply is right
  std::string property;  // what is checked of the reply and to what tolerance
};

class Session {
 public:
  virtual ~Session() = default;
  // Sends `request` with "exercise" and a fresh "id" added, and returns the reply object (its "id"
  // checked). Throws ChildFailure when there is no proper reply, StudentError when the reply
  // carries "error".
  virtual nlohmann::json ask(nlohmann::json request) = 0;
  // Seconds the program took per request over the current check (median); 0 before any request.
  virtual double seconds_per_request() const = 0;
  // A check begins: the request timings and the kept stderr start afresh, and a program that died
  // in the previous check is started again.
  virtual void begin_check() {}
  // What the program wrote to stderr during the current check (capped), taken out of the session.
  virtual std::string take_output() { return ""; }
  // What numlab expects of the reply to the last request (kept only where a check is recorded).
  virtual void expect(Expectation) {}
  // The forbidden library calls noticed since the last take (call_watch.hpp), taken out of the
  // session; none where the program is not watched.
  virtual LibraryCalls take_library_calls() { return {}; }
};

}  // namespace numlab::exercises
