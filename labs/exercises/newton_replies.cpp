#include "exercises/newton_replies.hpp"

#include <fmt/format.h>

#include "exercises/linkage_checks.hpp"

namespace numlab::exercises {

std::optional<Verdict> dishonest_reply(const NewtonReply& reply, double tolerance, long long max_iterations,
                                       double residual_rounding, const std::string& where) {
  if (reply.iterations > max_iterations || reply.iterations < 0) {
    return Verdict::fail(fmt::format("{}: iterations = {}, but max_iterations was {}", where, reply.iterations,
                                     max_iterations),
                         "the loop runs once more than allowed: stop when the count reaches max_iterations");
  }
  if (reply.status == "converged" && reply.residual_inf > tolerance + residual_rounding) {
    return Verdict::fail(
        fmt::format("{}: status \"converged\", but ||f(theta)||_inf = {} at your angles (numlab's closure), tolerance {} "
                    "(plus rounding {})",
                    where, sci(reply.residual_inf), sci(tolerance), sci(residual_rounding)),
        "only the residual test may say converged: max_i |f_i| <= tolerance, with abs, on every component (not "
        "|f_i + f_j|, not a signed test, not a small step)");
  }
  return std::nullopt;
}

}  // namespace numlab::exercises
