#include "exercises/linear_checks.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/format.h>

#include "exercises/reply_fields.hpp"

namespace numlab::exercises::linear {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

std::string sci(double value) { return fmt::format("{:.2g}", value); }

double relative_error(const Eigen::MatrixXd& x, const Eigen::MatrixXd& reference) {
  const double difference = (x - reference).cwiseAbs().maxCoeff();
  const double scale = reference.cwiseAbs().maxCoeff();
  return scale > 0.0 ? difference / scale : difference;
}

const nlohmann::json* optional_trace(const nlohmann::json& reply) {
  const auto found = reply.find("trace");
  if (found == reply.end()) return nullptr;
  if (!found->is_array()) throw ReplyError(fmt::format("\"trace\" is {}, not a list", found->type_name()));
  return &*found;
}

const nlohmann::json& trace_entry(const nlohmann::json& trace, std::size_t index) {
  const nlohmann::json& entry = trace[index];
  if (!entry.is_object()) throw ReplyError(fmt::format("trace[{}] is {}, not an object", index, entry.type_name()));
  return entry;
}

void ReferenceTimes::time(const std::string& name, const std::function<void()>& call) {
  constexpr int repeats = 5;
  std::vector<double> runs;
  for (int run = 0; run < repeats; ++run) {
    const auto begin = std::chrono::steady_clock::now();
    call();
    runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
  }
  if (!seconds_.count(name)) order_.push_back(name);
  seconds_[name].push_back(median(runs));
}

std::vector<ReferenceTime> ReferenceTimes::medians() const {
  std::vector<ReferenceTime> references;
  for (const std::string& name : order_) references.push_back({name, median(seconds_.at(name))});
  return references;
}

}  // namespace numlab::exercises::linear
