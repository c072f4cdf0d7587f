// `pmdplan validate TASK PATH.json`: an independent check of a path with the exact checker; a
// grasp path's closing phase with the grasp rule (hand-target contact allowed, nothing else).
#include <iostream>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/path_validation_json.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli::validate_command {
namespace {

struct Options {
  std::string task;
  std::string path;
  double toleranceMm = 1.0;
  bool json = false;
};

int run(const Options& o) {
  checkMotionToleranceMm(o.toleranceMm);
  const Task task = loadTaskByName(o.task);
  const PathFile file = readPathFile(o.path);
  if (file.jointNames != task.robot->activeJointNames())
    throw InputError(o.path, "joint_names",
                     "the path's joints do not match the active joints of robot '" + task.robot->name() + "'");
  ExactCollisionChecker checker(task);
  SegmentChecker segments(checker, *task.robot, o.toleranceMm / 1000.0);
  const PathPhases phases{file.closingFrom};
  PathValidation result;
  try {
    result = GraspRule(task).validatePath(checker, segments, file.points, phases);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(o.path, e.field(), e.message());  // the work bound (checkValidationWork) names the file
  }
  if (o.json) {
    std::cout << formatJson(pathValidationJson(result, phases, o.toleranceMm));
  } else {
    std::cout << o.path << ": " << (result.valid ? "valid" : "INVALID") << " (" << file.points.size() << " points, "
              << result.statesChecked << " states checked at " << o.toleranceMm << " mm"
              << (file.closingFrom
                      ? "; approach to point " + std::to_string(*file.closingFrom) + ", then closing on the target"
                      : "")
              << ")\n";
    for (const auto& p : result.problems) std::cout << "  " << p << "\n";
  }
  return result.valid ? 0 : 1;
}

const CommandRegistrar registrar{
    "validate", "Check a path file against a task with the exact checker", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option("task", o->task, "Built-in task name or task file")->required();
      app.add_option("path", o->path, "Path file (JSON) written by pmdplan plan")->required();
      app.add_option("--tolerance-mm", o->toleranceMm, "Motion check tolerance in millimetres");
      app.add_flag("--json", o->json, "Print JSON");
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::validate_command
