#pragma once
// What the linear exercises (gepp, gauss-seidel, inverse2x2) share: number formatting for messages,
// error measures, the optional "trace" of a reply, and the reference timings shown beside the
// student's ("speed is informative, never a failure").

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exercises/exercise.hpp"

namespace numlab::exercises::linear {

inline constexpr double eps = std::numeric_limits<double>::epsilon();

// A number for a message: 2 significant digits ("1.2e-12", "0.21", "57").
std::string sci(double value);

// ||x - reference||_inf / ||reference||_inf (absolute when the reference is 0).
double relative_error(const Eigen::MatrixXd& x, const Eigen::MatrixXd& reference);

// The reply's optional "trace": null when there is none; ReplyError when it is not a list.
const nlohmann::json* optional_trace(const nlohmann::json& reply);
// trace[index] as an object (ReplyError otherwise), for reply_fields' readers.
const nlohmann::json& trace_entry(const nlohmann::json& trace, std::size_t index);

// The time each reference takes per request, collected over a check's requests.
class ReferenceTimes {
 public:
  // Runs `call` a few times and keeps its median time under `name`.
  void time(const std::string& name, const std::function<void()>& call);
  // The median per reference over the requests timed, in the order first timed.
  std::vector<ReferenceTime> medians() const;

 private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> seconds_;
};

}  // namespace numlab::exercises::linear
