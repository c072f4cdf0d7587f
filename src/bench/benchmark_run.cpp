#include "pmdplan/bench/benchmark_run.hpp"

#include <algorithm>
#include <chrono>

#include "pmdplan/bench/human_likeness.hpp"
#include "pmdplan/bench/ompl_planning.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {
namespace {

void keepPath(const TaskBench& bench, const RunRecord& record, const std::vector<Configuration>& points,
              std::optional<std::size_t> closingFrom, const PlanningStatistics& statistics, PathFile* path) {
  if (!path) return;
  const Task& task = bench.task();
  *path = PathFile{task.name,
                   record.planner,
                   record.seed,
                   task.robot->activeJointNames(),
                   points,
                   closingFrom,
                   mimicRelations(*task.robot),
                   statistics};
}

RunRecord runPmdRoadmap(TaskBench& bench, const PlannerEntry& planner, RunRecord record,
                        const PlannerSettings& parameters, PathFile* path) {
  TaskPlanningSettings options;
  options.algorithm = planner.algorithm;
  options.mode = planner.mode;
  options.parameters = parameters;
  options.synergies = &bench.synergies();
  const TaskPlanningResult result = planTask(bench.task(), bench.checking(), options);
  const PlanningStatistics& s = result.statistics;
  record.solved = s.solved();
  record.planningTimeSeconds = s.planningTime;
  record.smoothingTimeSeconds = s.smoothingTime;
  record.samples = s.samples;
  record.armTrials = s.armTrials;
  record.maxTrials = s.maxTrials;
  record.finalArmHalfSize = s.finalArmHalfSize;
  record.nodesByHandDimension = s.nodesByHandDimension;
  record.roadmapNodes = s.roadmapNodes;
  record.collisionChecks = s.collisionChecks();
  if (record.solved) {
    assessPath(bench, result.path, record, result.closingFrom);
    keepPath(bench, record, result.path, result.closingFrom, s, path);
  } else {
    record.failure = "not solved: " + plannerStatusName(s.status);
  }
  return record;
}

RunRecord runOmpl(TaskBench& bench, const PlannerEntry& planner, RunRecord record, const PlannerSettings& parameters,
                  PathFile* path) {
  const Task& task = bench.task();
  MotionValidator& motions = bench.checking().motions();
  // A grasp goal as planTask plans it: OMPL's planner plans the approach to the pre-grasp (found
  // and timed the same way), the closing segment follows after smoothing.
  const TaskApproach approach = taskApproach(task, bench.checking(), GraspSettings{});
  const OmplPmdSampling pmdSampling{&bench.synergies(), parameters};
  const OmplPlanningResult result =
      planWithOmpl(planner.omplName, bench.space(), bench.checking().states(), motions, task.start, approach.end(task),
                   parameters.timeLimit, record.seed, planner.pmdSampling ? &pmdSampling : nullptr);
  record.solved = result.solved;
  record.planningTimeSeconds = result.planningTimeSeconds + approach.seconds;
  record.samples = result.stateChecks;
  record.roadmapNodes = result.graphStates;
  record.collisionChecks = result.stateChecks + result.motionChecks;
  if (!record.solved) {
    record.failure = "not solved: " + result.status;
    return record;
  }
  const std::size_t motionChecksBefore = motions.statesChecked();
  const auto began = std::chrono::steady_clock::now();
  std::vector<Configuration> smoothed = smoothPath(result.path, bench.space(), motions);
  record.smoothingTimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  record.collisionChecks += motions.statesChecked() - motionChecksBefore;
  const std::optional<std::size_t> closingFrom = appendClosing(task, approach, smoothed);
  assessPath(bench, smoothed, record, closingFrom);
  keepPath(bench, record, smoothed, closingFrom, PlanningStatistics{}, path);
  return record;
}

}  // namespace

RunRecord runPlannerOnce(TaskBench& bench, const PlannerEntry& planner, int run, const PlannerSettings& parameters,
                         PathFile* path) {
  RunRecord record;
  record.task = bench.task().name;
  record.planner = planner.name;
  record.run = run;
  record.seed = parameters.seed;
  return planner.family == PlannerFamily::Ompl ? runOmpl(bench, planner, record, parameters, path)
                                               : runPmdRoadmap(bench, planner, record, parameters, path);
}

void assessPath(TaskBench& bench, const std::vector<Configuration>& path, RunRecord& record,
                std::optional<std::size_t> closingFrom) {
  MotionValidator& motions = bench.checking().motions();
  // The approach: every point up to the pre-grasp (closingFrom), or the whole path.
  const std::size_t approachEnd = std::min(closingFrom ? *closingFrom + 1 : path.size(), path.size());
  const auto certificationBegan = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i + 1 < approachEnd; ++i) motions.isValid(path[i], path[i + 1]);
  record.certificationTimeSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - certificationBegan).count();
  record.pathNodes = path.size();
  record.pathLength = path.empty() ? 0.0 : pathLength(path, bench.space());
  if (!path.empty())
    record.humanLikeness = measureHumanLikeness(path, bench.space(), bench.synergies(), bench.synergySlots());
  const PathValidation validation =
      GraspRule(bench.task())
          .validatePath(bench.validationChecker(), bench.validationSegments(), path, PathPhases{closingFrom});
  record.valid = validation.valid;
  if (!validation.valid)
    record.failure = "invalid path: " + (validation.problems.empty() ? std::string("rejected by validation")
                                                                     : validation.problems.front());
}

}  // namespace pmdplan
