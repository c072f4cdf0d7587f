// `pmdplan check [TASK] [--json]`: are the task's start and goal valid (or is the goal a grasp of
// the target, and which pre-grasp will plan take), how far is each from the obstacles (clearance,
// or penetration depth), where is the palm, is the straight joint-space segment between them free
// at the motion tolerance, and will `plan` take the task (if not, why: the grasp rule's verdict,
// grasp_rule.hpp and grasp_approach.hpp)? The answers are taskCheckJson's (io/files/task_check_json.hpp),
// as Python's pmdplan.check. Exit 0 plan will take it, 1 plan will refuse it, 2 bad input.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "command_registry.hpp"
#include "grasp_options.hpp"
#include "package_path_option.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/io/files/task_check_json.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli::check_command {
namespace {

struct Options {
  std::string task = "can_on_table";
  bool json = false;
  double toleranceMm = 1.0;
  GraspOptions grasp;
};

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

int run(const Options& o) {
  checkMotionToleranceMm(o.toleranceMm);  // bad flags before the task is read
  const GraspSettings grasp = resolveGraspSettings(o.grasp);
  const Task task = loadTaskByName(o.task);
  const nlohmann::json out = taskCheckJson(task, o.toleranceMm, grasp);
  const nlohmann::json& plan = out["plan"];
  const int exitCode = plan["accepts"].get<bool>() ? 0 : 1;
  if (o.json) {
    std::cout << out.dump(2) << "\n";
    return exitCode;
  }
  const nlohmann::json& line = out["straight_line"];
  std::cout << "task " << task.name << " (" << task.file.string() << ")\n"
            << describe("start", out["start"]) << "\n"
            << describe("goal", out["goal"]) << "\n";
  if (line["free"].get<bool>()) {
    std::cout << "straight segment start -> goal: free (" << line["states_checked"].get<long>() << " states at "
              << o.toleranceMm << " mm)\n";
  } else {
    std::printf("straight segment start -> goal: in collision from %.1f %% of the way (state %ld of %ld at %g mm)\n",
                100.0 * line["first_collision"].get<double>(), line["states_checked"].get<long>(),
                line["states_needed"].get<long>(), o.toleranceMm);
    for (const auto& pair : line["collisions"])
      std::cout << "         collides: " << pair[0].get<std::string>() << " - " << pair[1].get<std::string>() << "\n";
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
