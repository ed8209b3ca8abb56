#pragma once
// The session the starter tests run the checker through: the student's program started in the
// starter's folder.

#include <memory>
#include <string>
#include <vector>

#include "exercises/session.hpp"

namespace numlab::test {

// `command` (its program looked up on PATH) run with `folder` as its working directory.
std::unique_ptr<exercises::Session> starter_session(const std::string& exercise, const std::string& folder,
                                                    const std::vector<std::string>& command);

}  // namespace numlab::test
