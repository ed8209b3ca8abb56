// linkage: f, J, poses and velocities of any linkage description file, against numlab's derived
// LinkageModel (its residual and analytic Jacobian) and its sweep (LinkageSweepStepper).

#include "exercises/linkage_exercise.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "exercises/linkage_checks.hpp"
#include "exercises/linkage_detectors.hpp"
#include "exercises/linkage_variant.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::LinkageModel;
using mechanisms::LinkageSolver;
using Evidence = std::optional<std::string>;
constexpr double eps = std::numeric_limits<double>::epsilon();

// What the battery works from: the model, numlab's solver on it, the poses swept and the poses
// where f and J are checked. Made once per battery.
struct LinkageCase {
  std::shared_ptr<const LinkageModel> model;
  std::shared_ptr<const LinkageModel> file_model;  // under a variant, the file's own (model is the variant's)
  std::unique_ptr<LinkageSolver> solver;
  nlohmann::json model_json;
  double size = 1.0;     // the longest link
  double reach = 1.0;    // the largest size of a coordinate or length: rounding in f is eps times this
  std::vector<double> drivers;         // user units, from the reference on
  std::vector<Eigen::VectorXd> poses;  // numlab's, one per driver
  std::vector<Eigen::VectorXd> velocities;
  double tolerance = 0.0;              // the residual the student's Newton must reach (absolute)
  struct ClosurePose {
    double driver;  // user units
    Eigen::VectorXd q;
    std::string text;
  };
  std::vector<ClosurePose> closure_poses;
  double step = 0.0, span = 0.0, direction = 0.0;  // the sweep: driver steps one way round from the reference
};

std::string vector_text(const Eigen::VectorXd& v) {
  std::string text;
  for (Eigen::Index k = 0; k < v.size(); ++k) text += fmt::format("{}{:.6g}", k > 0 ? ", " : "", v(k));
  return "[" + text + "]";
}

std::string driver_text(const LinkageModel& model, double driver) {
  return model.crank_driven() ? fmt::format("crank {:g} deg", driver) : fmt::format("travel {:g}", driver);
}

// numlab's sweep from the reference pose: 5-degree steps (a slider: size / 20) one way round, the
// poses that converged on the reference branch before any crossing, the longer way of the two.
// Under a variant (`file` given), the file's step, span and direction.
void sweep(LinkageCase& c, const LinkageCase* file = nullptr) {
  const LinkageModel& model = *c.model;
  const double reference = model.driver_to_user(c.solver->reference_driver());
  const double step = file ? file->step : model.crank_driven() ? 5.0 : c.size / 20.0;
  const double span = file ? file->span : model.crank_driven() ? 355.0 : 2.0 * c.size;
  c.step = step;
  c.span = span;
  for (double direction : {1.0, -1.0}) {
    if (file && direction != file->direction) continue;
    const auto result = mechanisms::linkage_sweep(*c.solver, reference, reference + direction * span, direction * step);
    double crossing = std::numeric_limits<double>::infinity();
    for (const auto& at : result.crossings) crossing = std::min(crossing, std::abs(at.driver - reference));
    std::vector<double> drivers;
    std::vector<Eigen::VectorXd> poses, velocities;
    for (const auto& pose : result.poses) {
      if (pose.outcome.status != Status::converged || !pose.branch_kept || pose.kinematics_by_differences) break;
      if (std::abs(pose.driver - reference) >= crossing - step) break;
      drivers.push_back(pose.driver);
      poses.push_back(pose.q);
      velocities.push_back(pose.velocity);
    }
    if (drivers.size() > c.drivers.size()) {
      c.direction = direction;
      c.drivers = drivers;
      c.poses = poses;
      c.velocities = velocities;
    }
  }
  if (c.drivers.size() < 2) {
    throw std::invalid_argument(fmt::format("exercise: the linkage '{}' does not move from its reference pose in "
                                            "steps of {:g}: no sweep to check",
                                            model.description().name, step));
  }
}

// Where f and J are checked: the reference pose, three swept poses, and two poses off any root
// (every term of every row counts there).
void closure_poses(LinkageCase& c) {
  const LinkageModel& model = *c.model;
  const std::size_t n = c.poses.size();
  for (std::size_t k : {std::size_t{0}, n / 4, n / 2, (3 * n) / 4}) {
    c.closure_poses.push_back({c.drivers[k], c.poses[k], "solved pose at " + driver_text(model, c.drivers[k])});
  }
  for (int shifted = 1; shifted <= 2; ++shifted) {
    Eigen::VectorXd q = c.poses[n / 3];
    for (Eigen::Index k = 0; k < q.size(); ++k) q(k) += 0.07 * c.size * std::sin(1.3 * static_cast<double>(k + shifted));
    const double driver = c.drivers[n / 3] + (model.crank_driven() ? 17.0 * shifted : 0.1 * c.size * shifted);
    c.closure_poses.push_back({driver, q, fmt::format("{}, q = {} (off any root)", driver_text(model, driver),
                                                      vector_text(q))});
  }
}

// The case of `model`; under a variant, `file` is the file's case, whose sweep the variant's must
// cover pose for pose (std::invalid_argument when it does not): its drivers are then the file's.
std::shared_ptr<const LinkageCase> make_case(std::shared_ptr<const LinkageModel> model, const LinkageCase* file = nullptr) {
  auto c = std::make_shared<LinkageCase>();
  c->model = std::move(model);
  mechanisms::LinkageSolverOptions options;
  options.newton.residual_tolerance = 1e-13;
  options.newton.max_iterations = 50;
  c->solver = std::make_unique<LinkageSolver>(*c->model, options);
  c->size = c->solver->size();
  c->model_json = linkage_model_json(*c->model);
  c->reach = c->size;
  for (const auto& joint : c->model->description().joints) c->reach = std::max(c->reach, joint.position.cwiseAbs().maxCoeff());
  c->tolerance = 1e-10 * c->size;
  sweep(*c, file);
  if (file) {
    const std::size_t n = file->drivers.size();
    if (c->drivers.size() < n || !std::equal(file->drivers.begin(), file->drivers.end(), c->drivers.begin()) ||
        (c->poses[0] - file->poses[0]).cwiseAbs().maxCoeff() > 0.1 * file->size) {
      throw std::invalid_argument("the variant's sweep does not cover the file's on its branch");
    }
    c->drivers.resize(n);
    c->poses.resize(n);
    c->velocities.resize(n);
    c->file_model = file->model;
  }
  for (const auto& q : c->poses) c->reach = std::max(c->reach, q.cwiseAbs().maxCoeff());
  closure_poses(*c);
  return c;
}

// The file's case without a variant; with one, the case of the variant's linkage (linkage_variant.hpp),
// drawn again until numlab's sweep covers the file's, pose for pose, from the same reference branch.
std::shared_ptr<const LinkageCase> case_for(std::shared_ptr<const LinkageModel> model, const Variant& variant) {
  const auto file = make_case(model);
  if (!variant.active()) return file;
  const auto varied = linkage_variant(model, variant, [&file](std::shared_ptr<const LinkageModel> candidate) {
    try {
      make_case(candidate, file.get());
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  });
  return make_case(varied, file.get());
}

// Under a variant, the student's numbers are the file's model's where the variant's belong: the
// mark of TASK.md's numbers typed in without a variant, or a model read from the file.
Evidence file_numbers_used(const LinkageCase& c, bool all_match, const std::string& what) {
  if (!c.file_model || !all_match) return std::nullopt;
  return fmt::format("your {} is the linkage of the file's own numbers, not your variant's: every link length, body "
                     "and ground joint of your variant differs from the file's by up to 3%; read them from the "
                     "request's \"model\" (TASK.md's equations are written with them)",
                     what);
}

// Rounding in f: the coordinates' differences carry eps times the largest coordinate.
double f_tolerance(const LinkageCase& c) { return 1e3 * eps * c.reach; }

nlohmann::json closure_request(const LinkageCase& c, const LinkageCase::ClosurePose& pose) {
  return {{"task", "closure"}, {"model", c.model_json}, {"driver", pose.driver}, {"q", to_json(pose.q)}};
}

std::vector<LinkageClosureSample> ask_closures(Session& session, const LinkageCase& c, bool want_J) {
  const LinkageModel& model = *c.model;
  const int m = model.equation_count(), n = model.unknown_count();
  std::vector<LinkageClosureSample> samples;
  for (const auto& pose : c.closure_poses) {
    const nlohmann::json reply = session.ask(closure_request(c, pose));
    LinkageClosureSample s;
    s.driver_user = pose.driver;
    s.t = model.driver_from_user(pose.driver);
    s.q = pose.q;
    model.residual(s.q, s.t, s.f_expected);
    model.jacobian(s.q, s.t, s.J_expected);
    if (want_J) {
      session.expect({pose.text, {{"J", to_json(s.J_expected)}},
                      fmt::format("each J[i][k] within {} of numlab's analytic J above",
                                  sci(1e3 * eps * s.J_expected.cwiseAbs().maxCoeff()))});
      s.J = matrix_field(reply, "J", m, n);
    } else {
      session.expect({pose.text, {{"f", to_json(s.f_expected)}},
                      fmt::format("each f[i] within {} of numlab's LinkageModel residual above", sci(f_tolerance(c)))});
      s.f = vector_field(reply, "f", m);
    }
    samples.push_back(std::move(s));
  }
  return samples;
}

std::vector<ReferenceTime> closure_time(const LinkageCase& c) {
  const auto& pose = c.closure_poses.front();
  Eigen::VectorXd f;
  Eigen::MatrixXd J;
  const double t = c.model->driver_from_user(pose.driver);
  const double seconds = median_seconds([&] {
    for (int i = 0; i < 100; ++i) {
      c.model->residual(pose.q, t, f);
      c.model->jacobian(pose.q, t, J);
    }
  });
  return {{"numlab LinkageModel (f and J)", seconds / 100.0}};
}

// Every sample's f (or J) is the file's model's at the same pose, to `tolerance`.
bool matches_file(const LinkageCase& c, const std::vector<LinkageClosureSample>& samples, double tolerance, bool J) {
  if (!c.file_model) return false;
  for (const auto& s : samples) {
    Eigen::VectorXd f;
    Eigen::MatrixXd jacobian;
    if (J) {
      c.file_model->jacobian(s.q, s.t, jacobian);
      if (s.J.rows() != jacobian.rows() || (s.J - jacobian).cwiseAbs().maxCoeff() > tolerance) return false;
    } else {
      c.file_model->residual(s.q, s.t, f);
      if (s.f.size() != f.size() || (s.f - f).cwiseAbs().maxCoeff() > tolerance) return false;
    }
  }
  return true;
}

Verdict check_f(Session& session, const LinkageCase& c) {
  const double tolerance = f_tolerance(c);
  const auto samples = ask_closures(session, c, false);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const auto& sample = samples[s];
    for (int i = 0; i < sample.f.size(); ++i) {
      if (std::abs(sample.f(i) - sample.f_expected(i)) <= tolerance) continue;
      return Verdict::fail(
          fmt::format("f[{}] ({}) = {} from numlab's LinkageModel at {}; allowed |error| {} (1e3 eps times the "
                      "largest coordinate or length, {:g})",
                      i, c.model->row_name(i), compared(sample.f(i), sample.f_expected(i)), c.closure_poses[s].text,
                      sci(tolerance), c.reach),
          more_specific(diagnose({{"wrong_link", Specificity::exact,
                                   [&] {
                                     return file_numbers_used(c, matches_file(c, samples, tolerance, false), "f");
                                   }}}),
                        diagnose(linkage_f_detectors(*c.model, samples, tolerance))),
          "compare the row with TASK.md's equation of the same number: same terms, same signs, the lengths of the file");
    }
  }
  return Verdict::pass(closure_time(c));
}

Verdict check_J(Session& session, const LinkageCase& c) {
  const auto samples = ask_closures(session, c, true);
  std::vector<double> tolerances;
  for (const auto& s : samples) tolerances.push_back(1e3 * eps * s.J_expected.cwiseAbs().maxCoeff());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const auto& sample = samples[s];
    for (int i = 0; i < sample.J.rows(); ++i) {
      for (int k = 0; k < sample.J.cols(); ++k) {
        if (std::abs(sample.J(i, k) - sample.J_expected(i, k)) <= tolerances[s]) continue;
        return Verdict::fail(
            fmt::format("J[{}][{}] = d f[{}] / d {} ({}) = {} from numlab's analytic LinkageModel J at {}; "
                        "allowed |error| {} (1e3 eps times max |J|)",
                        i, k, i, c.model->column_name(k), c.model->row_name(i),
                        compared(sample.J(i, k), sample.J_expected(i, k)), c.closure_poses[s].text, sci(tolerances[s])),
            more_specific(diagnose({{"wrong_link", Specificity::exact,
                                     [&] {
                                       return file_numbers_used(c, matches_file(c, samples, tolerances[s], true), "J");
                                     }}}),
                          diagnose(linkage_J_detectors(*c.model, samples, tolerances))),
            "J[i][k] is the derivative of TASK.md's row i by unknown k: a distance row gives (p_i - p_j) / L, a "
            "body row 1, -(1 - a), -a and +-b, a crank or slider row 1 or the line's direction");
      }
    }
  }
  return Verdict::pass(closure_time(c));
}

nlohmann::json sweep_request(const LinkageCase& c) {
  nlohmann::json drivers = nlohmann::json::array();
  for (double d : c.drivers) drivers.push_back(d);
  return {{"task", "sweep"},           {"model", c.model_json},           {"drivers", drivers},
          {"q0", to_json(c.poses[0])}, {"tolerance", c.tolerance}, {"max_iterations", 50}};
}

std::string sweep_inputs(const LinkageCase& c) {
  return fmt::format("{} poses, {} to {}, from numlab's reference pose", c.drivers.size(),
                     driver_text(*c.model, c.drivers.front()), driver_text(*c.model, c.drivers.back()));
}

// The reply's list `key` of one vector per driver.
std::vector<Eigen::VectorXd> per_pose(const nlohmann::json& reply, const std::string& key, std::size_t poses,
                                      Eigen::Index n) {
  const Eigen::MatrixXd rows = matrix_field(reply, key, static_cast<Eigen::Index>(poses), n);
  std::vector<Eigen::VectorXd> out;
  for (Eigen::Index k = 0; k < rows.rows(); ++k) out.push_back(rows.row(k).transpose());
  return out;
}

// How far the student's pose may be from numlab's: both solved to their residual tolerance, so
// each within ||J^-1|| times it of the root, ten times that, and rounding.
double position_tolerance(const LinkageCase& c, const Eigen::VectorXd& q, double driver) {
  Eigen::MatrixXd J;
  Eigen::VectorXd f;
  const double t = c.model->driver_from_user(driver);
  c.model->jacobian(q, t, J);
  c.model->residual(q, t, f);
  return 10.0 * inverse_inf_norm(J) * (c.tolerance + f.cwiseAbs().maxCoeff()) + 1e3 * eps * c.reach;
}

Verdict check_positions(Session& session, const LinkageCase& c) {
  const LinkageModel& model = *c.model;
  const nlohmann::json reply = session.ask(sweep_request(c));
  nlohmann::json expected = nlohmann::json::array();
  for (const auto& q : c.poses) expected.push_back(to_json(q));
  session.expect({sweep_inputs(c), {{"positions", expected}},
                  "each pose within 10 ||J^-1|| (tolerance + numlab's residual) of numlab's sweep above"});
  const auto positions = per_pose(reply, "positions", c.drivers.size(), model.unknown_count());
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const double allowed = position_tolerance(c, c.poses[k], c.drivers[k]);
    Eigen::Index worst;
    const double error = (positions[k] - c.poses[k]).cwiseAbs().maxCoeff(&worst);
    if (error <= allowed) continue;
    Eigen::VectorXd f;
    model.residual(positions[k], model.driver_from_user(c.drivers[k]), f);
    const double residual = f.cwiseAbs().maxCoeff();
    std::vector<Detector> detectors;
    detectors.push_back({"x_never_updated", Specificity::exact, [&]() -> std::optional<std::string> {
                           for (const auto& q : positions) {
                             if ((q - c.poses[0]).cwiseAbs().maxCoeff() > allowed) return std::nullopt;
                           }
                           return std::string("every pose you sent is q0: the Newton step never changed q");
                         }});
    detectors.push_back({"wrong_link", Specificity::exact, [&]() -> std::optional<std::string> {
                           if (!c.file_model) return std::nullopt;
                           Eigen::VectorXd g;
                           c.file_model->residual(positions[k], model.driver_from_user(c.drivers[k]), g);
                           return file_numbers_used(c, g.cwiseAbs().maxCoeff() <= 100.0 * c.tolerance, "pose");
                         }});
    if (model.crank_driven()) {
      detectors.push_back({"degrees_for_radians", Specificity::exact, [&]() -> std::optional<std::string> {
                             Eigen::VectorXd g;
                             model.residual(positions[k], c.drivers[k], g);
                             if (g.cwiseAbs().maxCoeff() > 100.0 * c.tolerance) return std::nullopt;
                             return fmt::format("your pose at {:g} deg closes the loop for a crank angle of {:g} "
                                                "radians: the driver is in degrees",
                                                c.drivers[k], c.drivers[k]);
                           }});
    }
    const std::string hint =
        residual <= 100.0 * c.tolerance
            ? "your pose closes the loop but is another assembly of the linkage: solve each pose by Newton from the "
              "pose before (the first from q0), in small steps, so the joints stay on q0's branch"
            : fmt::format("your pose does not close the loop: ||f||_inf = {} there, asked {}; iterate until "
                          "||f||_inf <= tolerance, with f and J of task 1",
                          sci(residual), sci(c.tolerance));
    return Verdict::fail(fmt::format("at {} (pose {} of {}): {} = {}, from numlab's sweep; allowed {} (10 ||J^-1|| "
                                     "(tolerance + residual) and rounding); your pose's ||f||_inf = {}",
                                     driver_text(model, c.drivers[k]), k + 1, positions.size(),
                                     model.column_name(static_cast<int>(worst)),
                                     compared(positions[k](worst), c.poses[k](worst)), sci(allowed), sci(residual)),
                         diagnose(detectors), hint);
  }
  return Verdict::pass();
}

Verdict check_velocities(Session& session, const LinkageCase& c) {
  const LinkageModel& model = *c.model;
  const nlohmann::json reply = session.ask(sweep_request(c));
  nlohmann::json expected = nlohmann::json::array();
  for (const auto& v : c.velocities) expected.push_back(to_json(v));
  session.expect({sweep_inputs(c), {{"velocities", expected}},
                  "each velocity within 10 kappa(J) (position tolerance / size + 1e3 eps) (|qdot| + size) of "
                  "numlab's J qdot = -dPhi/dt above"});
  const auto velocities = per_pose(reply, "velocities", c.drivers.size(), model.unknown_count());
  for (std::size_t k = 0; k < velocities.size(); ++k) {
    const double t = model.driver_from_user(c.drivers[k]);
    Eigen::MatrixXd J;
    Eigen::VectorXd phi_t;
    model.jacobian(c.poses[k], t, J);
    model.driver_derivative(c.poses[k], t, phi_t);
    const double scale = c.velocities[k].cwiseAbs().maxCoeff() + (model.crank_driven() ? c.size : 1.0);
    const double allowed =
        10.0 * kappa_inf(J) * (position_tolerance(c, c.poses[k], c.drivers[k]) / c.size + 1e3 * eps) * scale;
    Eigen::Index worst;
    const double error = (velocities[k] - c.velocities[k]).cwiseAbs().maxCoeff(&worst);
    if (error <= allowed) continue;
    return Verdict::fail(
        fmt::format("at {} (pose {} of {}): d {} / dt = {}, from numlab's J qdot = -dPhi/dt (t in {}); allowed {} "
                    "(10 kappa(J) (position tolerance / size + 1e3 eps) (|qdot| + size))",
                    driver_text(model, c.drivers[k]), k + 1, velocities.size(), model.column_name(static_cast<int>(worst)),
                    compared(velocities[k](worst), c.velocities[k](worst)),
                    model.crank_driven() ? "radians" : "length units", sci(allowed)),
        diagnose(linkage_velocity_detectors(velocities[k], c.velocities[k], J, phi_t, model.crank_driven(), allowed)),
        "solve J qdot = -dPhi/dt at each of your poses, with J of task 1 and dPhi/dt the derivative of the driver's "
        "rows by t");
  }
  return Verdict::pass();
}

Stubs linkage_stubs() {
  Stubs stubs;
  stubs.python =
      "    model = request[\"model\"]  # the unknowns, the equations in order (TASK.md)\n"
      "    if request[\"task\"] == \"closure\":\n"
      "        raise NotImplementedError(\"not implemented: f and J of the closure\")\n"
      "    raise NotImplementedError(\"not implemented: the poses and velocities over the sweep\")\n";
  stubs.cpp =
      "  if (request.at(\"task\") == \"closure\") throw std::runtime_error(\"not implemented: f and J of the closure\");\n"
      "  throw std::runtime_error(\"not implemented: the poses and velocities over the sweep\");\n";
  stubs.octave =
      "  if strcmp(request.task, 'closure')\n"
      "    error('not implemented: f and J of the closure');\n"
      "  end\n"
      "  error('not implemented: the poses and velocities over the sweep');\n";
  return stubs;
}

}  // namespace

Exercise linkage_exercise_without_model() {
  Exercise exercise;
  exercise.name = "linkage";
  exercise.summary = "f, J, poses and velocities of any linkage description file (needs --model FILE.toml|NAME)";
  exercise.task = task_text("linkage");
  exercise.stubs = linkage_stubs();
  exercise.battery = [](const Variant&) { return std::vector<Check>{}; };
  return exercise;
}

Exercise linkage_exercise(std::shared_ptr<const LinkageModel> model, const std::string& model_argument) {
  Exercise exercise = linkage_exercise_without_model();
  const std::string name = model->description().name;
  exercise.summary = "f, J, poses and velocities of the linkage '" + name + "'";
  // The linkage's own unknowns and equations, before the tasks that refer to them; under a variant,
  // written with the variant's numbers.
  const std::string generic = exercise.task;
  const auto task_of = [generic](const LinkageModel& linkage) {
    std::string task = generic;
    const std::size_t tasks = task.find("## Task 1");
    task.insert(tasks == std::string::npos ? task.size() : tasks, linkage_model_task(linkage) + "\n");
    return task;
  };
  exercise.task = task_of(*model);
  exercise.varied_task = [model, task_of](const Variant& variant) { return task_of(*case_for(model, variant)->model); };
  exercise.variant_task = [](const Variant&) {
    return std::string("Your linkage's numbers are not the file's: every link length, every body's local coordinates "
                       "and every ground joint's offset from the first ground joint is the file's times 1 + u, u within "
                       "3% (slider lines and the driver's reference stay). \"Your linkage\" above is written with "
                       "them, and every request's `model` carries them.\n");
  };
  exercise.arguments = {"--model", model_argument};
  exercise.battery = [model](const Variant& variant) {
    const auto c = case_for(model, variant);
    const std::size_t poses = c->closure_poses.size();
    return std::vector<Check>{
        {fmt::format("f follows TASK.md's {} equations of '{}' at {} poses, to rounding (1e3 eps of the largest "
                     "coordinate)",
                     model->equation_count(), model->description().name, poses),
         1, [c](Session& session) { return check_f(session, *c); }},
        {fmt::format("J is the derivative of f: every entry matches numlab's analytic Jacobian at {} poses", poses), 2,
         [c](Session& session) { return check_J(session, *c); }},
        {fmt::format("your Newton's poses over the sweep ({} poses) are numlab's, to 10 ||J^-1|| times the tolerance",
                     c->drivers.size()),
         3, [c](Session& session) { return check_positions(session, *c); }},
        {fmt::format("your velocities dq/dt over the sweep ({} poses) are numlab's J qdot = -dPhi/dt",
                     c->drivers.size()),
         4, [c](Session& session) { return check_velocities(session, *c); }},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
