// `pmdplan plan [TASK]`: any planner of the roster (the paper's PMD roadmap planner by default, its
// full-space baseline, ours, OMPL's) on a task, writing the path file. Exit 0 solved, 1 not solved
// within the limits, 2 bad input.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "command_registry.hpp"
#include "grasp_options.hpp"
#include "package_path_option.hpp"
#include "planner_setting_options.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/progress_line.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/io/files/path_csv.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/statistics_json.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_resolution.hpp"
#include "pmdplan/world/task.hpp"
#include "trajectory_output.hpp"

namespace pmdplan::cli::plan_command {
namespace {

/// The --planner help: our planners with what they are, then OMPL's names.
std::string plannerHelp() {
  std::string ours;
  std::string ompl;
  for (const PlannerEntry& entry : plannerRoster().entries()) {
    if (entry.family == PlannerFamily::Ompl)
      ompl += (ompl.empty() ? "" : ", ") + entry.name;
    else
      ours += (ours.empty() ? "" : ", ") + entry.name + " (" + entry.description + ")";
  }
  return ours + ", or one of OMPL's: " + ompl + " (docs/planners.md)";
}

struct Options {
  std::string task = "can_on_table";
  std::string planner = "pmd";
  std::string checker = "fast";
  std::string synergies;
  PlannerSettingOptions settings;
  double toleranceMm = 1.0;
  GraspOptions grasp;
  std::string output;
  std::string csv;
  bool json = false;
  std::optional<std::string> trajectory;  ///< --trajectory [F.json]: also time the path
};

int run(const Options& o) {
  const PlannerEntry* planner = findPlanner(o.planner);
  if (!planner)
    throw InputError("", "--planner", "'" + o.planner + "' is not a planner; expected " + knownPlannerNames());
  checkMotionToleranceMm(o.toleranceMm);
  const Task task = loadTaskByName(o.task);
  const CheckerKind checkerKind = checkerKindNamed(o.checker, "--checker");
  // A robot without groups is told how to get them before anything else.
  static_cast<void>(planningSpaceFromRobot(*task.robot));
  CollisionChecking checking(task, checkerKind, o.toleranceMm / 1000.0);
  // The goal may grasp the target (planTask checks it and refuses other contact).
  if (const auto refused = GraspRule(task).startRefusal(checking.exact())) refused->raise(task);

  const ResolvedSynergyModel synergies =
      planner->usesSynergies ? resolveSynergyModelForHand(*task.robot, o.synergies, SynergyModelNeed::Required)
                             : ResolvedSynergyModel{};
  // Every output is checked once the inputs are read (the task's files, the synergy model, the
  // joint limits), before the planning; the default name comes from the task file's name, never
  // from its contents.
  const std::filesystem::path output =
      o.output.empty() ? std::filesystem::path(resolveTaskPath(o.task).stem().string() + ".path.json")
                       : std::filesystem::path(o.output);
  checkOutputPath(output, "-o", {task.file, o.synergies});
  if (!o.csv.empty()) checkOutputPath(o.csv, "--csv", {task.file, o.synergies});
  const std::filesystem::path trajectoryFile = !o.trajectory           ? std::filesystem::path()
                                               : o.trajectory->empty() ? defaultTrajectoryFile(output)
                                                                       : std::filesystem::path(*o.trajectory);
  if (o.trajectory) checkTrajectoryOutputs(task, {}, trajectoryFile, "--trajectory");
  TaskPlanningSettings options;
  options.planner = planner;
  options.parameters = resolvePlannerSettings(o.settings, planner->mode);
  options.synergies = synergies.get();
  const PlannerSettings& parameters = options.parameters;
  options.grasp = resolveGraspSettings(o.grasp);
  ProgressLine progress("planning " + task.name);
  const TaskPlanningResult result = planTask(task, checking, options, [&](const PlannerProgress& p) {
    char status[160];
    std::snprintf(status, sizeof status, "sweep %zu rho_a %.4f  %zu samples  %zu nodes  %.1f s", p.sweep, p.armHalfSize,
                  p.samples, p.roadmapNodes, p.elapsedSeconds);
    progress.update(p.elapsedSeconds, parameters.timeLimit, status);
  });
  progress.finish();
  const PlannerStatus status = result.status;
  const auto& stats = result.statistics;

  std::string trajectorySummary;
  if (stats.solved()) {
    PathFile file{task.name,
                  o.planner,
                  parameters.seed,
                  task.robot->activeJointNames(),
                  result.path,
                  result.closingFrom,
                  mimicRelations(*task.robot),
                  stats};
    StagedOutputs staged;  // renamed together once every output is written
    writePathFile(output, file);
    if (!o.csv.empty()) writePathCsv(o.csv, file.jointNames, file.points);
    if (o.trajectory) trajectorySummary = writeTimedTrajectory(task, checking, file, {}, trajectoryFile);
    staged.commit();
  }
  if (o.json) {
    auto document = statisticsToJson(stats, true);
    std::cout << formatJson(document) << "\n";
  } else if (stats.solved()) {
    std::printf("%s: solved with the %s planner (seed %llu) in %.3f s + %.3f s smoothing\n", task.name.c_str(),
                o.planner.c_str(), static_cast<unsigned long long>(parameters.seed), stats.planningTime,
                stats.smoothingTime);
    if (planner->family == PlannerFamily::Ompl)
      std::printf("  %zu states checked, %zu graph states\n", stats.samples, stats.roadmapNodes);
    else
      std::printf(
          "  %zu samples (hand-arm draws) from %zu arm trials, %zu roadmap nodes, max trials %zu, final rho_a %.4f\n",
          stats.samples, stats.armTrials, stats.roadmapNodes, stats.maxTrials, stats.finalArmHalfSize);
    std::printf("  %zu path nodes, length %.3f (normalised)\n", stats.pathNodes, stats.pathLength);
    if (result.grasp)
      std::printf("  grasp of %s: approach to a pre-grasp (%s, %.1f mm from it), then closing (points %zu-%zu)\n",
                  task.target->c_str(), result.grasp->derived ? "the goal hand opened" : "the task's pregrasp",
                  1000.0 * result.grasp->clearance, *result.closingFrom, result.path.size() - 1);
    std::printf("  path written to %s\n%s", output.string().c_str(), trajectorySummary.c_str());
  } else {
    std::printf("%s: not solved (%s) after %.1f s, %zu samples, %zu roadmap nodes\n", task.name.c_str(),
                plannerStatusName(status).c_str(), stats.planningTime, stats.samples, stats.roadmapNodes);
  }
  return stats.solved() ? 0 : 1;
}

const CommandRegistrar registrar{
    "plan", "Plan a path for a task with a planner (default: the paper's PMD roadmap planner)", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option("task", o->task, "Built-in task name or task file (default can_on_table)");
      app.add_option("--planner", o->planner, plannerHelp());
      app.add_option(
          "--checker", o->checker,
          "fast (default: convex parts and lane kernels, FCL only near contact; the same answers) or exact (FCL only)");
      app.add_option("--synergies", o->synergies, "Synergy model file (default: the robot's shipped model)");
      app.add_option("--tolerance-mm", o->toleranceMm, "Motion check tolerance in millimetres");
      addPlannerSettingOptions(app, o->settings);
      addGraspOptions(app, o->grasp);
      app.add_option("-o,--output", o->output, "Path file to write (default: TASK's file name with .path.json, here)");
      app.add_option("--csv", o->csv, "Also write the waypoints as CSV");
      std::string keys;
      for (const char* key : statisticsJsonKeys()) keys += (keys.empty() ? "" : ", ") + std::string(key);
      app.add_flag("--json", o->json, "Print the statistics as JSON (keys: " + keys + ")");
      app.add_option("--trajectory", o->trajectory,
                     "Also write the time-optimal trajectory (default TASK.trajectory.json) and its CSV")
          ->expected(0, 1);
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::plan_command
