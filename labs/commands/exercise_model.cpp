#include "commands/exercise_model.hpp"

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "commands/linkage_command.hpp"
#include "exercises/linkage_exercise.hpp"
#include "numlab/mechanisms/linkage/linkage_description.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::cli {

NamedExercise exercise_named(const std::string& name, const std::string& model, const std::string& verb,
                             const std::string& model_argument) {
  if (name != "linkage") {
    if (!model.empty()) {
      throw std::invalid_argument("exercise " + verb + ": --model applies to the linkage exercise only, not '" + name +
                                  "'");
    }
    return {exercises::find_exercise(name), "", false};
  }
  if (model.empty()) {
    throw std::invalid_argument("exercise " + verb +
                                ": linkage needs --model FILE.toml or a shipped model's NAME (numlab models lists them)");
  }
  const std::string file = linkage_file_for(model);
  if (file.empty()) {
    throw std::invalid_argument("exercise " + verb + ": --model '" + model +
                                "' is neither a file nor a shipped model (numlab models lists them)");
  }
  std::error_code error;
  const bool shipped = !std::filesystem::is_regular_file(model, error);
  auto derived = std::make_shared<const mechanisms::LinkageModel>(mechanisms::read_linkage_description(file));
  if (derived->has_second_driver()) {
    throw std::invalid_argument("exercise " + verb + ": --model '" + model + "' has two drivers (mobility 2); the linkage "
                                "exercise's requests give one driver value: choose a linkage with one driver");
  }
  return {exercises::linkage_exercise(derived, model_argument.empty() ? model : model_argument), file, shipped};
}

}  // namespace numlab::cli
