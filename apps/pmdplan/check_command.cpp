// `pmdplan check [TASK] [--json]`: are the task's start and goal valid (or is the goal a grasp of
// the target, and which pre-grasp will plan take), how far is each from the obstacles (clearance,
// or penetration depth), where is the palm, is the straight joint-space segment between them free
// at the motion tolerance, and will `plan` take the task (if not, why: the grasp rule's verdict,
// grasp_rule.hpp and grasp_approach.hpp)? Exit 0 plan will take it, 1 plan will refuse it, 2 bad
// input.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command_registry.hpp"
#include "grasp_options.hpp"
#include "package_path_option.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/grasp_approach.hpp"
#include "pmdplan/world/task.hpp"
#include "robot_setup.hpp"

namespace pmdplan::cli::check_command {
namespace {

struct Options {
  std::string task = "can_on_table";
  bool json = false;
  double toleranceMm = 1.0;
  GraspOptions grasp;
};

nlohmann::json pairsJson(const CollisionReport& report) {
  auto pairs = nlohmann::json::array();
  for (const auto& [a, b] : report.pairs) pairs.push_back({a, b});
  return pairs;
}

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json configurationJson(ExactCollisionChecker& checker, const Configuration& q) {
  const auto report = checker.check(q);
  const auto& model = checker.model();
  if (model.palmLink() < 0)
    throw InputError(model.urdfPath().string(), "end_effector",
                     "the robot names no palm link; write its SRDF with " + robotInitHint(model.urdfPath()));
  const Eigen::Isometry3d palm = checker.kinematics().linkPoses(q)[static_cast<std::size_t>(model.palmLink())];
  const auto clearance = checker.clearance(q);
  return {{"valid", report.free()},
          {"collisions", pairsJson(report)},
          {"clearance_mm", clearance ? nlohmann::json(1000.0 * clearance->metres) : nlohmann::json()},
          {"nearest", clearance ? nlohmann::json{clearance->pair.first, clearance->pair.second} : nlohmann::json()},
          {"palm_position", vectorJson(palm.translation())},
          {"palm_z_axis", vectorJson(palm.linear().col(2))}};
}

std::string describe(const std::string& label, const nlohmann::json& c) {
  char line[256];
  const auto& p = c["palm_position"];
  const auto& z = c["palm_z_axis"];
  // A grasp's contact with its target is allowed contact, not a collision (grasp_rule.hpp).
  const bool grasp = c.contains("grasp");
  std::snprintf(line, sizeof line, "%-6s %-9s palm at (%.4f, %.4f, %.4f) m, palm z (%.3f, %.3f, %.3f)", label.c_str(),
                grasp                    ? "GRASP"
                : c["valid"].get<bool>() ? "valid"
                                         : "IN COLLISION",
                p[0].get<double>(), p[1].get<double>(), p[2].get<double>(), z[0].get<double>(), z[1].get<double>(),
                z[2].get<double>());
  std::string text = line;
  if (!c["clearance_mm"].is_null()) {
    const double mm = c["clearance_mm"].get<double>();
    std::snprintf(line, sizeof line, "\n         %s %.2f mm (%s - %s)", mm < 0.0 ? "penetration" : "clearance",
                  std::abs(mm), c["nearest"][0].get<std::string>().c_str(), c["nearest"][1].get<std::string>().c_str());
    text += line;
  }
  if (grasp) {
    text += "\n         grasps the target " + c["grasp"].get<std::string>() + ": planned as an approach";
    if (c.contains("pregrasp")) {
      const auto& pregrasp = c["pregrasp"];
      std::snprintf(line, sizeof line, " to a pre-grasp (%s, %.1f mm from the target)",
                    pregrasp["derived"].get<bool>() ? "the goal hand opened" : "the task's pregrasp",
                    pregrasp["clearance_mm"].get<double>());
      text += line;
    }
    text += ", then closing";
  }
  for (const auto& pair : c["collisions"])
    text += std::string("\n         ") + (grasp ? "grasp contact (allowed): " : "collides: ") +
            pair[0].get<std::string>() + " - " + pair[1].get<std::string>();
  return text;
}

/// What plan will make of the task: the refusals (start, goal or pre-grasp), and on the goal a
/// grasp's target and pre-grasp.
nlohmann::json planVerdict(ExactCollisionChecker& checker, const Task& task, double tolerance,
                           const GraspSettings& grasp, nlohmann::json& goal) {
  auto refusals = nlohmann::json::array();
  const auto add = [&](const PlanRefusal& refusal) {
    refusals.push_back({{"field", refusal.field}, {"reason", refusal.reason}, {"pairs", pairsJson(refusal.pairs)}});
  };
  if (const auto start = GraspRule(task).startRefusal(checker)) add(*start);
  const GoalExamination examined = examineGoal(task, checker, tolerance, grasp);
  if (examined.contact.contact == GoalContact::GraspsTarget) goal["grasp"] = *task.target;
  if (const auto& a = examined.approach)
    goal["pregrasp"] = {{"derived", a->derived}, {"opening", a->opening}, {"clearance_mm", 1000.0 * a->clearance}};
  if (examined.refusal) add(*examined.refusal);
  return {{"accepts", refusals.empty()}, {"refusals", std::move(refusals)}};
}

int run(const Options& o) {
  checkMotionToleranceMm(o.toleranceMm);
  const GraspSettings grasp = resolveGraspSettings(o.grasp);
  const Task task = loadTaskByName(o.task);
  ExactCollisionChecker checker(task);
  SegmentChecker segments(checker, *task.robot, o.toleranceMm / 1000.0);
  try {  // the straight segment's states, bounded as validate's (collision/path_validation.hpp)
    checkValidationWork(segments, {task.start, task.goal});
  } catch (const InputError& e) {
    throw InputError(o.task, "start, goal", e.message());
  }
  const auto start = configurationJson(checker, task.start);
  auto goal = configurationJson(checker, task.goal);
  const nlohmann::json plan = planVerdict(checker, task, o.toleranceMm / 1000.0, grasp, goal);
  const int exitCode = plan["accepts"].get<bool>() ? 0 : 1;
  const auto line = segments.inspect(checker, task.start, task.goal);
  nlohmann::json straight = {
      {"free", line.free},
      {"first_collision", line.firstCollision ? nlohmann::json(*line.firstCollision) : nlohmann::json()},
      {"collisions", pairsJson(line.collisions)},
      {"states_checked", line.statesChecked},
      {"states_needed", line.statesNeeded},
      {"tolerance_mm", o.toleranceMm}};
  if (o.json) {
    nlohmann::json out = {
        {"task", task.name}, {"start", start}, {"goal", goal}, {"straight_line", straight}, {"plan", plan}};
    std::cout << out.dump(2) << "\n";
    return exitCode;
  }
  std::cout << "task " << task.name << " (" << task.file.string() << ")\n"
            << describe("start", start) << "\n"
            << describe("goal", goal) << "\n";
  if (line.free) {
    std::cout << "straight segment start -> goal: free (" << line.statesChecked << " states at " << o.toleranceMm
              << " mm)\n";
  } else {
    std::printf("straight segment start -> goal: in collision from %.1f %% of the way (state %ld of %ld at %g mm)\n",
                100.0 * *line.firstCollision, line.statesChecked, line.statesNeeded, o.toleranceMm);
    for (const auto& [a, b] : line.collisions.pairs) std::cout << "         collides: " << a << " - " << b << "\n";
  }
  for (const auto& refusal : plan["refusals"])
    std::cout << "plan will refuse the task's " << refusal["field"].get<std::string>() << ": "
              << refusal["reason"].get<std::string>() << "\n";
  if (exitCode == 0) std::cout << "plan will take the task\n";
  return exitCode;
}

const CommandRegistrar registrar{
    "check", "Check a task: start and goal validity, palm poses, the straight segment, whether plan will take it",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option("task", o->task, "Built-in task name or task file (default can_on_table)");
      app.add_flag("--json", o->json, "Print JSON instead of text");
      app.add_option("--tolerance-mm", o->toleranceMm, "Motion check tolerance in millimetres");
      addGraspOptions(app, o->grasp);
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::check_command
