// `pmdplan plan [TASK]`: the paper's PMD roadmap planner (or its full-space baseline) on a task,
// writing the path file. Exit 0 solved, 1 not solved within the limits, 2 bad input.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "command_registry.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/progress_line.hpp"
#include "pmdplan/io/json_text.hpp"
#include "pmdplan/io/path_csv.hpp"
#include "pmdplan/io/path_file.hpp"
#include "pmdplan/io/robot_mimic.hpp"
#include "pmdplan/io/statistics_json.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli {
namespace {

struct Options {
  std::string task = "can_on_table";
  std::string planner = "pmd";
  std::string checker = "fast";
  std::string synergies;
  std::uint64_t seed = 1;
  double timeLimit = 60.0;
  double toleranceMm = 1.0;
  double neighbourThreshold = PlannerParameters{}.neighbourThresholdFactor;
  std::string output;
  std::string csv;
  bool json = false;
};

std::string pairsText(const CollisionReport& report) {
  std::string text;
  for (const auto& [a, b] : report.pairs) text += (text.empty() ? "" : ", ") + a + " - " + b;
  return text;
}

int run(const Options& o) {
  const auto mode = parseHandSamplingMode(o.planner);
  if (!mode) throw InputError("", "--planner", "'" + o.planner + "' is not a planner; expected pmd or full");
  checkMotionToleranceMm(o.toleranceMm);
  const Task task = loadTaskByName(o.task);
  const std::filesystem::path output = o.output.empty() ? std::filesystem::path(task.name + ".path.json") : std::filesystem::path(o.output);
  checkOutputPath(output, "-o", {task.file, o.synergies});
  if (!o.csv.empty()) checkOutputPath(o.csv, "--csv", {task.file, o.synergies, output});
  const auto checkerKind = parseCheckerKind(o.checker);
  if (!checkerKind) throw InputError("", "--checker", "'" + o.checker + "' is not a checker; expected exact or fast");
  CollisionChecking checking(task, *checkerKind, o.toleranceMm / 1000.0);
  for (const auto& [label, q] : {std::pair{"start", &task.start}, std::pair{"goal", &task.goal}}) {
    const auto report = checking.exact().check(*q);
    if (!report.free())
      throw InputError(task.file.string(), label, std::string("the ") + label + " configuration is in collision: " + pairsText(report));
  }

  const std::filesystem::path synergyFile =
      o.synergies.empty() ? dataDirectory() / "synergies" / (task.robot->name() + "_default.yaml") : std::filesystem::path(o.synergies);
  std::optional<SynergyModel> synergies;
  if (*mode == HandSamplingMode::Synergy) synergies = loadSynergyModel(synergyFile);
  TaskPlanningOptions options;
  options.mode = *mode;
  options.parameters = PlannerParameters::defaultsFor(*mode);
  options.parameters.seed = o.seed;
  options.parameters.timeLimit = o.timeLimit;
  options.parameters.neighbourThresholdFactor = o.neighbourThreshold;
  options.synergies = synergies ? &*synergies : nullptr;
  try {
    options.parameters.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());
  }
  ProgressLine progress("planning " + task.name);
  TaskPlanningResult result;
  try {
    result = planTask(task, checking, options, [&](const PlannerProgress& p) {
      char status[160];
      std::snprintf(status, sizeof status, "sweep %zu rho_a %.4f  %zu samples  %zu nodes  %.1f s", p.sweep, p.armHalfSize,
                    p.samples, p.roadmapNodes, p.elapsedSeconds);
      progress.update(p.elapsedSeconds, o.timeLimit, status);
    });
  } catch (const InputError& e) {
    if (!e.file().empty() || e.field().rfind("--", 0) == 0) throw;
    throw InputError(synergyFile.string(), e.field(), e.message());  // the sampler names the model's field
  }
  progress.finish();
  const PlannerStatus status = result.status;
  const auto& stats = result.statistics;

  if (stats.solved()) {
    PathFile file{task.name, o.planner, o.seed, task.robot->activeJointNames(), result.path, mimicRelations(*task.robot), stats};
    writePathFile(output, file);
    if (!o.csv.empty()) writePathCsv(o.csv, file.jointNames, file.points);
  }
  if (o.json) {
    auto document = statisticsToJson(stats, true);
    std::cout << formatJson(document) << "\n";
  } else if (stats.solved()) {
    std::printf("%s: solved with the %s planner (seed %llu) in %.3f s + %.3f s smoothing\n", task.name.c_str(), o.planner.c_str(),
                static_cast<unsigned long long>(o.seed), stats.planningTime, stats.smoothingTime);
    std::printf("  %zu samples, %zu roadmap nodes, final rho_a %.4f, %zu path nodes, length %.3f (normalised)\n", stats.samples,
                stats.roadmapNodes, stats.finalArmHalfSize, stats.pathNodes, stats.pathLength);
    std::printf("  path written to %s\n", output.string().c_str());
  } else {
    std::printf("%s: not solved (%s) after %.1f s, %zu samples, %zu roadmap nodes\n", task.name.c_str(),
                plannerStatusName(status).c_str(), stats.planningTime, stats.samples, stats.roadmapNodes);
  }
  return stats.solved() ? 0 : 1;
}

const CommandRegistrar registrar{"plan", "Plan a path for a task with the PMD roadmap planner", [](CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("task", o->task, "Built-in task name or task file (default can_on_table)");
  app.add_option("--planner", o->planner, "pmd (the paper's planner) or full (hands sampled over the whole joint box)");
  app.add_option("--checker", o->checker, "fast (default: sphere model, FCL on flagged pairs; the same answers) or exact (FCL only)");
  app.add_option("--synergies", o->synergies, "Synergy model file (default: the robot's shipped model)");
  app.add_option("--seed", o->seed, "Random seed (a whole number >= 0)")->check(wholeNumber());
  app.add_option("--time-limit", o->timeLimit, "Wall-clock limit in seconds");
  app.add_option("--tolerance-mm", o->toleranceMm, "Motion check tolerance in millimetres");
  app.add_option("--neighbour-threshold", o->neighbourThreshold, "Neighbour radius as a multiple of d(start, goal)");
  app.add_option("-o,--output", o->output, "Path file to write (default TASK.path.json)");
  app.add_option("--csv", o->csv, "Also write the waypoints as CSV");
  app.add_flag("--json", o->json, "Print the statistics as JSON");
  return [o] { return run(*o); };
}};

}  // namespace
}  // namespace pmdplan::cli
