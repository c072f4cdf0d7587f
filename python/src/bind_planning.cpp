// pmdplan.plan: any planner of the roster on a task, through the library's planTask.
// Planning releases the GIL; errors are the CLI's (InputError, the same messages).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <optional>

#include "bindings.hpp"
#include "conversions.hpp"
#include "planner_settings.hpp"
#include "pmdplan/bench/human_likeness.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/path_validation_json.hpp"
#include "pmdplan/io/files/statistics_json.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"
#include "python_interrupt.hpp"

namespace pmdplan::python {
namespace {

/// What pmdplan.plan returns.
struct PyPlanResult {
  std::string task;
  std::string planner;
  std::uint64_t seed = 0;
  std::vector<std::string> jointNames;
  std::vector<Configuration> path;
  std::optional<std::size_t> closingFrom;  ///< a grasp path's closing phase (docs/grasp_goals.md)
  PlanningStatistics statistics;
  std::vector<MimicRelation> mimic;
  double callSeconds = 0.0;  ///< wall time of the library call alone (planTask)
};

py::object jsonToPython(const nlohmann::ordered_json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

/// Throws the CLI's InputError if plan refuses the task's start or goal (the grasp rule: a goal
/// may grasp the target, grasp_rule.hpp and grasp_approach.hpp).
void requirePlannableEnds(const Task& task, PyCollisionChecker& checker) {
  py::gil_scoped_release release;
  std::lock_guard lock(checker.mutex);
  if (const auto refused = GraspRule(task).startRefusal(checker.checking->exact())) refused->raise(task);
  graspApproach(task, checker.checking->exact(), checker.checking->tolerance());
}

/// The checker to plan with: the caller's, or a new one of the named kind.
std::shared_ptr<PyCollisionChecker> checkerFor(const PyTask& task, py::handle checker, double toleranceMm) {
  if (py::isinstance<PyCollisionChecker>(checker)) {
    auto given = checker.cast<std::shared_ptr<PyCollisionChecker>>();
    if (given->world != task.world)
      throw InputError("", "checker",
                       "the CollisionChecker was made for another robot, base or obstacles than this task's");
    return given;
  }
  if (!py::isinstance<py::str>(checker))
    throw InputError("", "checker", "expected 'fast', 'exact' or a pmdplan.CollisionChecker");
  auto made = std::make_shared<PyCollisionChecker>();
  made->task = task.task;
  made->world = task.world;
  made->checking = std::make_unique<CollisionChecking>(*task.task, parseCheckerOption(checker.cast<std::string>()),
                                                       parseToleranceOption(toleranceMm));
  return made;
}

PyPlanResult plan(const PyTask& task, const std::string& planner, py::handle settings, py::handle checker,
                  py::handle synergies, std::optional<std::uint64_t> seed, std::optional<double> timeLimit,
                  double toleranceMm) {
  const PlannerEntry* entry = &plannerNamed(planner, "planner");
  auto checking = checkerFor(task, checker, toleranceMm);
  PythonInterrupt interrupt;  // Ctrl-C ends the run as its time limit would, then raises KeyboardInterrupt
  std::optional<PySynergyModel> model;
  if (entry->usesSynergies) model = synergyModelArgument(*task.task, synergies);
  TaskPlanningSettings options;
  options.planner = entry;
  options.parameters = plannerParametersFrom(settings, entry->mode, seed, timeLimit);
  options.synergies = model ? model->model.get() : nullptr;
  checkPlannerParameters(options.parameters);
  PyPlanResult result;
  TaskPlanningResult planned;
  try {
    py::gil_scoped_release release;
    std::lock_guard lock(checking->mutex);
    const auto began = std::chrono::steady_clock::now();
    planned = planTask(*task.task, *checking->checking, options);
    result.callSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  } catch (const InputError& e) {
    if (!e.file().empty() || !model) throw;
    throw InputError(model->source, e.field(), e.message());  // the sampler names the model's field
  }
  interrupt.raiseIfInterrupted();
  // The CLI's message for a start or goal plan refuses (every planner stops at once with that status).
  if (planned.status == PlannerStatus::InvalidStart || planned.status == PlannerStatus::InvalidGoal)
    requirePlannableEnds(*task.task, *checking);
  result.task = task.task->name;
  result.planner = entry->name;
  result.seed = seedOf(options.parameters);
  result.jointNames = task.task->robot->activeJointNames();
  result.path = std::move(planned.path);
  result.closingFrom = planned.closingFrom;
  result.statistics = planned.statistics;
  result.mimic = mimicRelations(*task.task->robot);
  return result;
}

void bindResult(py::module_& m) {
  py::class_<PyPlanResult>(m, "PlanResult",
                           "One planner run: status, the path (points, dof) in radians, the statistics.")
      .def_readonly("task", &PyPlanResult::task)
      .def_readonly("planner", &PyPlanResult::planner)
      .def_readonly("seed", &PyPlanResult::seed)
      .def_readonly("joint_names", &PyPlanResult::jointNames)
      .def_readonly("call_seconds", &PyPlanResult::callSeconds, "Wall time of the library's planning call alone.")
      .def_property_readonly(
          "status", [](const PyPlanResult& r) { return plannerStatusName(r.statistics.status); },
          "solved, sample_limit, time_limit, invalid_start or invalid_goal.")
      .def_property_readonly("solved", [](const PyPlanResult& r) { return r.statistics.solved(); })
      .def_readonly("closing_from", &PyPlanResult::closingFrom,
                    "A grasp path's closing phase: the index of its first point (the pre-grasp), or None.")
      .def_property_readonly(
          "path", [](const PyPlanResult& r) { return pathArray(r.path, static_cast<int>(r.jointNames.size())); },
          "(points, dof) float64 array, start first and goal last; empty unless solved.")
      .def_property_readonly(
          "statistics", [](const PyPlanResult& r) { return jsonToPython(statisticsToJson(r.statistics, true)); },
          "The statistics with the keys of `pmdplan plan --json`.")
      .def(
          "save",
          [](const PyPlanResult& r, const std::filesystem::path& file) {
            const CommandFileScope files;  // the output rule of the CLI (core/command_files.hpp)
            if (!r.statistics.solved())
              throw InputError(file.string(), "", "the run did not solve: there is no path to write");
            writePathFile(
                file, PathFile{r.task, r.planner, r.seed, r.jointNames, r.path, r.closingFrom, r.mimic, r.statistics});
          },
          py::arg("file"), "Writes the path file (JSON), as `pmdplan plan -o` does.")
      .def("__repr__", [](const PyPlanResult& r) {
        return "<pmdplan.PlanResult " + r.planner + " on " + r.task + ": " + plannerStatusName(r.statistics.status) +
               ", " + std::to_string(r.path.size()) + " points>";
      });
}

}  // namespace

void bindPlanning(py::module_& m) {
  bindResult(m);
  m.def(
      "planners",
      [] {
        std::vector<std::string> names;
        for (const PlannerEntry& entry : plannerRoster().entries()) names.push_back(entry.name);
        return names;
      },
      "Every planner name plan() takes: pmd, full, ompl:RRTConnect, ...");
  m.def("plan", &plan, py::arg("task"), py::arg("planner") = "pmd", py::kw_only(), py::arg("settings") = py::none(),
        py::arg("checker") = "fast", py::arg("synergies") = py::none(), py::arg("seed") = py::none(),
        py::arg("time_limit") = py::none(), py::arg("tolerance_mm") = 1.0,
        "Plans task with planner 'pmd' (the paper's), 'full' (its full-space baseline), 'pmd-lazy', 'pmd-connect'\n"
        "or 'ompl:<Name>[@pmd]' (planners()). settings: PlannerSettings (OMPL's planners honour its seed, time\n"
        "limit, smoothing and PMD sampling); seed and time_limit override it. checker: 'fast', 'exact' or a\n"
        "CollisionChecker of this task (reused; its tolerance applies). synergies: SynergyModel, a model file or\n"
        "None (the robot's shipped model). The GIL is released while planning. OMPL planners seed OMPL's\n"
        "process-wide generator, which OMPL honours only before its first random number in a process.\n"
        "Raises InputError with the CLI's messages (bad planner, colliding start or goal, bad settings, model).");
}

}  // namespace pmdplan::python
