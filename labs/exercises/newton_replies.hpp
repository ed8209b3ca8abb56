#pragma once
// What jansen-newton and mustang-newton check in every Newton reply: the iteration limit kept, and
// a status "converged" backed by the residual test at the returned angles (recomputed by numlab).

#include <optional>
#include <string>

#include "exercises/exercise.hpp"

namespace numlab::exercises {

struct NewtonReply {
  std::string status;
  long long iterations = 0;
  double residual_inf = 0.0;  // ||f||_inf at the returned angles, by numlab's closure
};

// A failed Verdict when the reply claims more than it shows, else nothing. `where` names the
// request ("crank 130 deg"); `residual_rounding` is what re-evaluating f adds (1e3 eps L).
std::optional<Verdict> dishonest_reply(const NewtonReply& reply, double tolerance, long long max_iterations,
                                       double residual_rounding, const std::string& where);

}  // namespace numlab::exercises
