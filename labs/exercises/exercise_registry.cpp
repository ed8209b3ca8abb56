#include <algorithm>
#include <stdexcept>

#include "exercises/exercise.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/linkage_exercise.hpp"

namespace numlab::exercises {

const std::vector<Exercise>& all_exercises() {
  static const std::vector<Exercise> exercises = {
      gepp_exercise(),
      gauss_seidel_exercise(),
      inverse2x2_exercise(),
      polyfit_exercise(),
      jansen_jacobian_exercise(),
      jansen10_jacobian_exercise(),
      jansen_newton_exercise(),
      mustang_newton_exercise(),
      linkage_exercise_without_model(),  // made for a model by linkage_exercise() (--model)
  };
  return exercises;
}

const Exercise& find_exercise(const std::string& name) {
  const auto& exercises = all_exercises();
  const auto found = std::find_if(exercises.begin(), exercises.end(),
                                  [&](const Exercise& exercise) { return exercise.name == name; });
  if (found != exercises.end()) return *found;
  throw std::invalid_argument("exercise: unknown exercise '" + name + "' (numlab exercise list names them)");
}

}  // namespace numlab::exercises
