// `pmdplan time PATH.json [--task TASK] [-o F.json] [timing options]`: the path timed optimally
// under the robot's joint velocity and acceleration limits (Kunz & Stilman's TOTG with circular
// blends), written as a JointTrajectory-shaped JSON and CSV.
#include <cstdio>
#include <memory>

#include "command_registry.hpp"
#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/viewer/path_robot_match.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/world/task.hpp"
#include "trajectory_output.hpp"

namespace pmdplan::cli::time_command {
namespace {

struct Options {
  std::string path;
  std::string task;
  std::string output;
  std::string checker = "fast";
  double toleranceMm = 1.0;
  TrajectoryOutputOptions trajectory;
};

int run(const Options& o) {
  const PathFile path = readPathFile(o.path);
  Task task;
  try {
    task = loadTaskByName(o.task.empty() ? path.task : o.task);
  } catch (const InputError& error) {
    if (!error.file().empty() || !o.task.empty()) throw;
    throw InputError(o.path, "task", error.message() + "; give the task with --task TASK");
  }
  PathFile checked = path;
  checked.points = pathConfigurations(path, *task.robot, o.path);
  checked.jointNames = task.robot->activeJointNames();
  checked.mimic = mimicRelations(*task.robot);
  const CheckerKind checkerKind = checkerKindNamed(o.checker, "--checker");
  if (!(o.toleranceMm > 0.0)) throw InputError("", "--tolerance-mm", "expected a positive number of millimetres");
  CollisionChecking checking(task, checkerKind, o.toleranceMm / 1000.0);
  const std::filesystem::path output =
      o.output.empty() ? defaultTrajectoryFile(o.path) : std::filesystem::path(o.output);
  checkTrajectoryOutputs(task, o.trajectory, output, "-o");  // against every input read so far
  std::printf("%s: timing %zu waypoints\n", o.path.c_str(), checked.points.size());
  StagedOutputs staged;  // the JSON and its CSV renamed together
  const std::string summary = writeTimedTrajectory(task, checking, checked, o.trajectory, output);
  staged.commit();
  std::fputs(summary.c_str(), stdout);
  return 0;
}

const CommandRegistrar registrar{
    "time", "Time a path optimally under the joints' velocity and acceleration limits", [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      app.add_option("path", o->path, "Path file (JSON) written by pmdplan plan")->required();
      app.add_option("--task", o->task, "Task name or file (default: the task the path file names)");
      app.add_option("-o,--output", o->output,
                     "Trajectory file to write (default PATH's name with .trajectory.json; the CSV beside it)");
      app.add_option("--checker", o->checker, "Checker for the blends: fast (default) or exact");
      app.add_option("--tolerance-mm", o->toleranceMm, "Blend check tolerance in millimetres (default 1)");
      addTrajectoryOptions(app, o->trajectory);
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::time_command
