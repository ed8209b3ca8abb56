#pragma once
// numlab exercise: the protocol loop for a student's C++ solution. The student writes
//
//   nlohmann::json solve(const nlohmann::json& request);
//
// and main() returns numlab::exercise::serve(solve). serve() reads one JSON request per line from
// stdin, answers each with one JSON line on stdout (the request's "id" echoed), and returns when
// stdin closes. An exception from solve() becomes the reply {"id": ..., "error": "what()"}, so a
// stub that throws "not implemented" fails its checks honestly instead of crashing.
// Write diagnostics to std::cerr: the checker keeps them as the check's output.

#include <exception>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace numlab::exercise {

using Matrix = std::vector<std::vector<double>>;
using Vector = std::vector<double>;

// A request's matrix (a list of rows) or vector, e.g. matrix(request["A"]).
inline Matrix matrix(const nlohmann::json& rows) { return rows.get<Matrix>(); }
inline Vector vector(const nlohmann::json& list) { return list.get<Vector>(); }

template <class Solve>
int serve(Solve&& solve) {
  std::string line;
  while (std::getline(std::cin, line)) {
    if (line.empty()) continue;
    nlohmann::json reply;
    nlohmann::json id = nullptr;
    try {
      const nlohmann::json request = nlohmann::json::parse(line);
      id = request.value("id", nlohmann::json());
      reply = solve(request);
    } catch (const std::exception& error) {
      reply = {{"error", error.what()}};
    }
    reply["id"] = id;
    std::cout << reply.dump() << std::endl;  // endl flushes: the checker waits for this line
  }
  return 0;
}

}  // namespace numlab::exercise
