// pmdplan.CollisionChecker: the state and segment checks of one task, with the fast checker's
// batches for arrays of configurations; pmdplan.check: `pmdplan check` of a task
// (io/files/task_check_json.hpp). The GIL is released while checking.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>

#include "bindings.hpp"
#include "conversions.hpp"
#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/task_check_json.hpp"

namespace pmdplan::python {
namespace {

CheckerKind checkerKindFrom(const std::string& name) { return checkerKindNamed(name, "checker"); }

double toleranceMetres(double toleranceMm) {
  try {
    checkMotionToleranceMm(toleranceMm);  // the CLI's rule and message
  } catch (const InputError& e) {
    throw InputError(e.file(), "tolerance_mm", e.message());  // the argument's Python name
  }
  return toleranceMm / 1000.0;
}

const JointLimits& jointsOf(const PyCollisionChecker& c) { return c.task->robot->activeJoints(); }

/// valid[i] for every configuration: the fast checker in batches of its lane count, else one by one.
std::vector<bool> checkAll(PyCollisionChecker& c, const std::vector<Configuration>& configurations) {
  std::vector<bool> result(configurations.size());
  py::gil_scoped_release release;
  std::lock_guard lock(c.mutex);
  auto* fast = dynamic_cast<FastCollisionChecker*>(&c.checking->states());
  if (!fast) {
    for (std::size_t i = 0; i < configurations.size(); ++i) result[i] = c.checking->states().isValid(configurations[i]);
    return result;
  }
  constexpr int kLanes = FastCollisionChecker::kLanes;
  const Configuration* batch[kLanes];
  bool valid[kLanes];
  double safe[kLanes];
  for (std::size_t first = 0; first < configurations.size(); first += kLanes) {
    const int count = static_cast<int>(std::min<std::size_t>(kLanes, configurations.size() - first));
    for (int i = 0; i < count; ++i) batch[i] = &configurations[first + static_cast<std::size_t>(i)];
    fast->checkBatch(batch, count, valid, safe);
    for (int i = 0; i < count; ++i) result[first + static_cast<std::size_t>(i)] = valid[i];
  }
  return result;
}

/// `check(checking, q)` on one configuration argument, with the GIL released and the checker locked.
template <typename Check>
auto onConfiguration(PyCollisionChecker& c, py::handle q, Check check) {
  const Configuration configuration = jointValuesFrom(jointsOf(c), q, "configuration");
  py::gil_scoped_release release;
  std::lock_guard lock(c.mutex);
  return check(*c.checking, configuration);
}

}  // namespace

CheckerKind parseCheckerOption(const std::string& name) { return checkerKindFrom(name); }
double parseToleranceOption(double toleranceMm) { return toleranceMetres(toleranceMm); }

void bindCollision(py::module_& m) {
  py::class_<PyCollisionChecker, std::shared_ptr<PyCollisionChecker>>(
      m, "CollisionChecker",
      "The collision checks of one task: 'fast' (default; the same answers as 'exact') or 'exact' (FCL).\n"
      "Segments are straight in joint space, free up to tolerance_mm (no robot point moves more between\n"
      "two checked states).")
      .def(py::init([](const PyTask& task, const std::string& checker, double toleranceMm) {
             auto c = std::make_shared<PyCollisionChecker>();
             c->task = task.task;
             c->world = task.world;
             c->checking =
                 std::make_unique<CollisionChecking>(*c->task, checkerKindFrom(checker), toleranceMetres(toleranceMm));
             return c;
           }),
           py::arg("task"), py::arg("checker") = "fast", py::arg("tolerance_mm") = 1.0)
      .def_property_readonly("task",
                             [](const PyCollisionChecker& c) {
                               return PyTask{c.task, c.world};
                             })
      .def_property_readonly("checker", [](const PyCollisionChecker& c) { return checkerKindName(c.checking->kind()); })
      .def_property_readonly("tolerance_mm",
                             [](const PyCollisionChecker& c) { return c.checking->tolerance() * 1000.0; })
      .def(
          "is_valid",
          [](PyCollisionChecker& c, py::handle q) {
            return onConfiguration(c, q, [](CollisionChecking& checking, const Configuration& configuration) {
              return checking.states().isValid(configuration);
            });
          },
          py::arg("configuration"), "True if the configuration (array or {joint: radians}) is free of collisions.")
      .def(
          "colliding_pairs",
          [](PyCollisionChecker& c, py::handle q) {
            return onConfiguration(c, q, [](CollisionChecking& checking, const Configuration& configuration) {
              return checking.exact().check(configuration).pairs;
            });
          },
          py::arg("configuration"),
          "Every colliding pair (link - link or link - obstacle names), by the exact checker; [] when free.")
      .def(
          "check_batch",
          [](PyCollisionChecker& c, py::handle configurations) {
            const auto all = configurationsFrom(jointsOf(c), configurations, "configurations");
            const std::vector<bool> valid = checkAll(c, all);
            py::array_t<bool> result(static_cast<py::ssize_t>(valid.size()));
            auto out = result.mutable_unchecked<1>();
            for (std::size_t i = 0; i < valid.size(); ++i) out(static_cast<py::ssize_t>(i)) = valid[i];
            return result;
          },
          py::arg("configurations"),
          "Validity of every row of an (n, dof) array, as a bool array (the fast checker batches them).")
      .def(
          "is_segment_free",
          [](PyCollisionChecker& c, py::handle from, py::handle to) {
            const Configuration a = jointValuesFrom(jointsOf(c), from, "from");
            const Configuration b = jointValuesFrom(jointsOf(c), to, "to");
            py::gil_scoped_release release;
            std::lock_guard lock(c.mutex);
            return c.checking->states().isValid(a) && c.checking->states().isValid(b) &&
                   c.checking->motions().isValid(a, b);
          },
          py::arg("from_configuration"), py::arg("to_configuration"),
          "True if both ends and the straight joint-space segment between them are free at the tolerance.")
      .def(
          "is_path_free",
          [](PyCollisionChecker& c, py::handle path) {
            const auto points = configurationsFrom(jointsOf(c), path, "path");
            py::gil_scoped_release release;
            std::lock_guard lock(c.mutex);
            for (std::size_t i = 0; i < points.size(); ++i) {
              if (!c.checking->states().isValid(points[i])) return false;
              if (i > 0 && !c.checking->motions().isValid(points[i - 1], points[i])) return false;
            }
            return true;
          },
          py::arg("path"),
          "True if every point of an (n, dof) path and every segment between consecutive points is free.")
      .def_property_readonly(
          "state_checks",
          [](PyCollisionChecker& c) {
            std::lock_guard lock(c.mutex);
            return c.checking->states().checkCount();
          },
          "Configurations checked so far.")
      .def("__repr__", [](const PyCollisionChecker& c) {
        return "<pmdplan.CollisionChecker " + checkerKindName(c.checking->kind()) + " for " + c.task->name + ">";
      });
  m.def(
      "check",
      [](const PyTask& task, double toleranceMm) {
        nlohmann::json document;
        {
          py::gil_scoped_release release;
          document = taskCheckJson(*task.task, toleranceMm);
        }
        return pythonFromJson(document);
      },
      py::arg("task"), py::arg("tolerance_mm") = 1.0,
      "`pmdplan check --json` of a task: its start and goal (validity, pairs, clearance, palm pose), the\n"
      "straight segment between them, and whether plan takes the task ({'accepts', 'refusals'}).");
}

}  // namespace pmdplan::python
