#include "pmdplan/bench/benchmark_run.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "pmdplan/bench/human_likeness.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/task_planning.hpp"

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

}  // namespace

RunRecord runPlannerOnce(TaskBench& bench, const PlannerEntry& planner, int run, const PlannerSettings& parameters,
                         PathFile* path) {
  RunRecord record;
  record.task = bench.task().name;
  record.planner = planner.name;
  record.run = run;
  record.seed = parameters.seed;
  TaskPlanningSettings options;
  options.planner = &planner;
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
