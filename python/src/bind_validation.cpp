// pmdplan.validate (the independent exact check of a path, validatePathFile / validateTaskPath in
// io/files/path_file_validation.hpp, as `pmdplan validate`) and pmdplan.human_likeness (the
// benchmarks' measure, bench/human_likeness.hpp). The checks release the GIL; errors are the CLI's.
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>

#include "bindings.hpp"
#include "conversions.hpp"
#include "pmdplan/bench/human_likeness.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/stop_request.hpp"
#include "pmdplan/io/files/path_file_validation.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"
#include "python_interrupt.hpp"

namespace pmdplan::python {
namespace {

bool isPathFileArgument(py::handle path) { return py::isinstance<py::str>(path) || py::hasattr(path, "__fspath__"); }

py::object validatePathArgument(const PyTask& task, py::handle path, double toleranceMm,
                                std::optional<std::size_t> closingFrom) {
  const Task& t = *task.task;
  std::optional<std::filesystem::path> file;
  std::vector<Configuration> points;
  if (isPathFileArgument(path)) {
    file = std::filesystem::path(py::str(path).cast<std::string>());
    if (closingFrom)
      throw InputError(file->string(), "closing_from",
                       "a path file gives its own phases; pass closing_from with an array only");
  } else {
    points = configurationsFrom(t.robot->activeJoints(), path, "path", false);
  }
  PathJudgement judgement;
  PythonInterrupt interrupt;  // Ctrl-C stops the check at its next state and raises KeyboardInterrupt
  try {
    py::gil_scoped_release release;
    judgement = file ? validatePathFile(t, *file, toleranceMm)
                     : validateTaskPath(t, points, PathPhases{closingFrom}, toleranceMm);
  } catch (const StopRequested&) {
    interrupt.raiseIfInterrupted();
    throw;
  }
  return pythonFromJson(pathJudgementJson(judgement));
}

py::dict measureHumanLikenessArgument(const PyTask& task, py::handle path, py::handle synergies, double step,
                                      int subspaceDirections) {
  const auto points = configurationsFrom(task.task->robot->activeJoints(), path, "path", false);
  if (points.empty()) throw InputError("", "path", "expected at least one configuration");
  if (!(step > 0.0)) throw InputError("", "step", "expected a positive step in normalised joint units");
  if (subspaceDirections < 0) throw InputError("", "subspace_directions", "expected a number of directions >= 0");
  const PySynergyModel model = synergyModelArgument(*task.task, synergies);
  const auto slots = modelJointSlots(*model.model, *task.task->robot, model.source);
  HumanLikenessSettings settings;
  settings.step = step;
  settings.subspaceDirections = subspaceDirections;
  const HumanLikeness measured =
      measureHumanLikeness(points, planningSpaceFromRobot(*task.task->robot), *model.model, slots, settings);
  py::dict result;
  result["subspace_distance_mean"] = measured.subspaceDistanceMean;
  result["subspace_distance_max"] = measured.subspaceDistanceMax;
  result["mahalanobis_mean"] = measured.mahalanobisMean;
  return result;
}

}  // namespace

void bindValidation(py::module_& m) {
  m.def("validate", &validatePathArgument, py::arg("task"), py::arg("path"), py::arg("tolerance_mm") = 1.0,
        py::kw_only(), py::arg("closing_from") = py::none(),
        "The independent check of `pmdplan validate`, by the same grasp rule: path is an (n, dof) array or a\n"
        "path file (whose phases count). closing_from (arrays only): a grasp path's closing phase starts at that\n"
        "point (PlanResult.closing_from), with hand-target contact allowed from there. Returns {'valid',\n"
        "'states_checked', 'tolerance_mm', 'closing_from', 'collisions', 'problems'} (`pmdplan validate --json`).");
  m.def("human_likeness", &measureHumanLikenessArgument, py::arg("task"), py::arg("path"),
        py::arg("synergies") = py::none(), py::arg("step") = 0.01,
        py::arg("subspace_directions") = HumanLikenessSettings{}.subspaceDirections,
        "How human-like a path's hand motion is (the benchmarks' measure): {'subspace_distance_mean',\n"
        "'subspace_distance_max', 'mahalanobis_mean'}, walked along the path at `step` (normalised units).");
}

}  // namespace pmdplan::python
