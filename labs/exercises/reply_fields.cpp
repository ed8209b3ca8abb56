#include "exercises/reply_fields.hpp"

#include <cmath>
#include <fmt/format.h>

namespace numlab::exercises {

namespace {

const nlohmann::json& field(const nlohmann::json& reply, const std::string& key) {
  const auto found = reply.find(key);
  if (found == reply.end()) throw ReplyError(fmt::format("the reply has no \"{}\"", key));
  return *found;
}

// One entry of a list, as a finite number; `where` names it in the message ("x[3]", "J[2][5]").
double finite_entry(const nlohmann::json& entry, const std::string& where) {
  if (!entry.is_number()) {
    throw ReplyError(fmt::format("{} is {}, not a number", where, entry.is_null() ? "null" : entry.type_name()));
  }
  const double value = entry.get<double>();
  if (!std::isfinite(value)) throw ReplyError(fmt::format("{} is not finite", where));
  return value;
}

void require_list(const nlohmann::json& value, const std::string& where, Eigen::Index size) {
  if (!value.is_array()) throw ReplyError(fmt::format("{} is {}, not a list", where, value.type_name()));
  if (static_cast<Eigen::Index>(value.size()) != size) {
    throw ReplyError(fmt::format("{} has {} entries, expected {}", where, value.size(), size));
  }
}

}  // namespace

Eigen::VectorXd vector_field(const nlohmann::json& reply, const std::string& key, Eigen::Index n) {
  const nlohmann::json& list = field(reply, key);
  require_list(list, key, n);
  Eigen::VectorXd vector(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    vector(i) = finite_entry(list[static_cast<std::size_t>(i)], fmt::format("{}[{}]", key, i));
  }
  return vector;
}

Eigen::MatrixXd matrix_field(const nlohmann::json& reply, const std::string& key, Eigen::Index rows,
                             Eigen::Index cols) {
  const nlohmann::json& list = field(reply, key);
  require_list(list, key, rows);
  Eigen::MatrixXd matrix(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const nlohmann::json& row = list[static_cast<std::size_t>(i)];
    require_list(row, fmt::format("{}[{}]", key, i), cols);
    for (Eigen::Index j = 0; j < cols; ++j) {
      matrix(i, j) = finite_entry(row[static_cast<std::size_t>(j)], fmt::format("{}[{}][{}]", key, i, j));
    }
  }
  return matrix;
}

double number_field(const nlohmann::json& reply, const std::string& key) {
  return finite_entry(field(reply, key), key);
}

long long integer_field(const nlohmann::json& reply, const std::string& key) {
  const nlohmann::json& value = field(reply, key);
  if (value.is_number_integer()) return value.get<long long>();
  // A tolerant reader takes 13.0 for 13: JSON has one number type, and Octave's jsonencode, or a
  // float counter in Python, may write a whole number with a fraction.
  if (value.is_number_float()) {
    const double number = value.get<double>();
    constexpr double limit = 9.2e18;  // inside long long's range
    if (std::isfinite(number) && number == std::trunc(number) && std::abs(number) < limit) {
      return static_cast<long long>(number);
    }
    throw ReplyError(fmt::format("\"{}\" is {}, not a whole number", key, value.dump()));
  }
  throw ReplyError(fmt::format("\"{}\" is {}, not a whole number", key, value.type_name()));
}

std::string string_field(const nlohmann::json& reply, const std::string& key) {
  const nlohmann::json& value = field(reply, key);
  if (!value.is_string()) throw ReplyError(fmt::format("\"{}\" is {}, not a string", key, value.type_name()));
  return value.get<std::string>();
}

std::optional<std::string> optional_status(const nlohmann::json& reply) {
  if (!reply.contains("status")) return std::nullopt;
  return string_field(reply, "status");
}

nlohmann::json to_json(const Eigen::MatrixXd& matrix) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) row.push_back(matrix(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

nlohmann::json to_json(const Eigen::VectorXd& vector) {
  nlohmann::json list = nlohmann::json::array();
  for (Eigen::Index i = 0; i < vector.size(); ++i) list.push_back(vector(i));
  return list;
}

}  // namespace numlab::exercises
