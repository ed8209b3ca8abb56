#pragma once
// The linkage exercise (docs/exercises.md, "Any linkage as an exercise"): any linkage description
// file (docs/linkage-files.md) or shipped model becomes an exercise. The student writes f and J of
// the closure in the unknowns numlab derives from the file (the moving joints' x and y), and the
// poses and velocities over a sweep of the driver with a Newton solver of their own; the checks
// compare them with numlab's LinkageModel and its sweep (mechanisms/linkage/).
//
// The registry holds the exercise without a model (for `exercise list` and `show linkage`); the
// command makes the real one from --model with linkage_exercise().

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "exercises/exercise.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::exercises {

// The exercise for `model`. `model_argument` is what the starter's check command passes as
// --model (a shipped model's NAME, or the file name the starter folder holds).
Exercise linkage_exercise(std::shared_ptr<const mechanisms::LinkageModel> model, const std::string& model_argument);

// The exercise as `exercise list` and `show linkage` see it without --model: the generic task, and a
// battery that has no checks (check, grade and init refuse linkage without --model).
Exercise linkage_exercise_without_model();

// The model as every request carries it: joints, unknowns, driver, equations in row order.
nlohmann::json linkage_model_json(const mechanisms::LinkageModel& model);

// The part of TASK.md made from the model: its joints, unknowns, driver and equations, numbered.
std::string linkage_model_task(const mechanisms::LinkageModel& model);

}  // namespace numlab::exercises
