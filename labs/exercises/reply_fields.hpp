#pragma once
// Reading a reply's fields with their sizes checked: a missing field, a wrong size, a string where
// a number belongs, or NaN/infinity is not an answer but a broken reply (ReplyError: the check is
// an `error`, with a message naming the field and what was expected).

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

namespace numlab::exercises {

class ReplyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// reply[key] as a vector of exactly n finite numbers.
Eigen::VectorXd vector_field(const nlohmann::json& reply, const std::string& key, Eigen::Index n);
// reply[key] as `rows` lists of `cols` finite numbers.
Eigen::MatrixXd matrix_field(const nlohmann::json& reply, const std::string& key, Eigen::Index rows,
                             Eigen::Index cols);
// reply[key] as a finite number / a whole number (13 or 13.0, not 13.5) / a string.
double number_field(const nlohmann::json& reply, const std::string& key);
long long integer_field(const nlohmann::json& reply, const std::string& key);
std::string string_field(const nlohmann::json& reply, const std::string& key);
// reply["status"] when present (a string), otherwise nothing.
std::optional<std::string> optional_status(const nlohmann::json& reply);

// Requests carry matrices as lists of rows and vectors as lists.
nlohmann::json to_json(const Eigen::MatrixXd& matrix);
nlohmann::json to_json(const Eigen::VectorXd& vector);

}  // namespace numlab::exercises
