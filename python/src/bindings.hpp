#pragma once
// The parts of the Python module pmdplan._core, one function per binding file (module.cpp calls
// them in order), and the Python-side holders of the library's objects.
#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/synergy_model.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::python {

namespace py = pybind11;

/// pmdplan.Robot: a loaded robot model, shared by the tasks made for it.
struct PyRobot {
  std::shared_ptr<const RobotModel> model;
};

/// pmdplan.Task: immutable once made (replace() makes a new one), shared with the checkers.
struct PyTask {
  std::shared_ptr<const Task> task;
  /// The robot, base and obstacles: tasks made by replace() with the same ones share it, and so
  /// may share a CollisionChecker (only the start and goal differ).
  std::shared_ptr<const int> world;
};

/// pmdplan.CollisionChecker: the checks of one task. The library's checkers keep state between
/// calls, so every use (checks, plans) holds `mutex` while the GIL is released.
struct PyCollisionChecker {
  std::shared_ptr<const Task> task;
  std::shared_ptr<const int> world;  ///< of `task`
  std::unique_ptr<CollisionChecking> checking;
  std::mutex mutex;
};

/// pmdplan.SynergyModel: a model with the file it came from (messages name it), if any.
struct PySynergyModel {
  std::shared_ptr<const SynergyModel> model;
  std::string source;
};

/// The CLI's --checker and --tolerance-mm values, with its messages (InputError).
CheckerKind parseCheckerOption(const std::string& name);
double parseToleranceOption(double toleranceMm);

/// A `synergies` argument: a SynergyModel, a model file, or None for the robot's shipped model
/// (resolveSynergyModel, synergy/synergy_model_resolution.hpp, with its message for a robot that
/// ships none, field "synergies").
PySynergyModel synergyModelArgument(const Task& task, py::handle synergies);

void bindErrors(py::module_& m);
void bindRobotAndTask(py::module_& m);
void bindCollision(py::module_& m);
void bindSynergies(py::module_& m);
void bindPlannerSettings(py::module_& m);
void bindPlanning(py::module_& m);
void bindValidation(py::module_& m);

}  // namespace pmdplan::python
