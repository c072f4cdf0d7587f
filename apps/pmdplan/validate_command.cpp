// `pmdplan validate TASK PATH.json`: an independent check of a path with the exact checker; a
// grasp path's closing phase with the grasp rule (hand-target contact allowed, nothing else). The
// check is validatePathFile (io/files/path_file_validation.hpp), as Python's pmdplan.validate.
#include <iostream>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/io/files/path_file_validation.hpp"
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
  checkMotionToleranceMm(o.toleranceMm);  // a bad tolerance before the task is read
  const Task task = loadTaskByName(o.task);
  const PathJudgement judgement = validatePathFile(task, o.path, o.toleranceMm);
  const PathValidation& result = judgement.validation;
  const auto& closingFrom = judgement.phases.closingFrom;
  if (o.json) {
    std::cout << formatJson(pathJudgementJson(judgement));
  } else {
    std::cout << o.path << ": " << (result.valid ? "valid" : "INVALID") << " (" << judgement.pointCount << " points, "
              << result.statesChecked << " states checked at " << o.toleranceMm << " mm"
              << (closingFrom ? "; approach to point " + std::to_string(*closingFrom) + ", then closing on the target"
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
