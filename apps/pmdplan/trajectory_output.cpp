#include "trajectory_output.hpp"

#include <cstdio>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/trajectory/collision_free_timing.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"

namespace pmdplan::cli {

void addTrajectoryOptions(CLI::App& app, TrajectoryOutputOptions& o) {
  app.add_option("--blend-tolerance", o.timing.blendTolerance,
                 "Largest distance (rad, joint space) of a corner blend from its waypoint; 0 stops at every waypoint "
                 "(default 0.01)");
  app.add_option("--velocity-scale", o.timing.velocityScale,
                 "Fraction of the joints' velocity limits used (default 1)");
  app.add_option("--acceleration-scale", o.timing.accelerationScale,
                 "Fraction of the joints' acceleration limits used (default 1)");
  app.add_option("--joint-limits", o.jointLimits,
                 "Joint-limits YAML (default: ROBOT.joint_limits.yaml beside the URDF)");
  app.add_option("--sample-interval", o.sampleInterval, "Seconds between the trajectory's points (default 0.01)");
}

std::filesystem::path defaultTrajectoryFile(const std::filesystem::path& pathFile) {
  std::string stem = pathFile.filename().string();
  if (const auto dot = stem.find(".path.json"); dot != std::string::npos)
    stem.erase(dot);
  else
    stem = pathFile.stem().string();
  return pathFile.parent_path() / (stem + ".trajectory.json");
}

std::string writeTimedTrajectory(const Task& task, CollisionChecking& checking, const PathFile& path,
                                 const TrajectoryOutputOptions& options, const std::filesystem::path& output) {
  try {
    options.timing.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());
  }
  if (!(options.sampleInterval > 0.0 && options.sampleInterval <= 1.0))
    throw InputError("", "--sample-interval", "expected seconds in (0, 1]");
  const auto limits = jointMotionLimits(*task.robot, options.jointLimits.empty()
                                                         ? std::nullopt
                                                         : std::optional<std::filesystem::path>(options.jointLimits));
  const SweptDistanceBound bound(*task.robot);
  const CollisionFreeTiming timing =
      timeCollisionFree(path.points, limits, options.timing, checking.states(), bound, checking.tolerance());
  TrajectoryFile file;
  file.task = path.task;
  file.planner = path.planner;
  file.seed = path.seed;
  file.mimic = path.mimic;
  for (const auto& limit : limits) {
    file.velocityLimits.push_back(limit.velocity * options.timing.velocityScale);
    file.accelerationLimits.push_back(limit.acceleration * options.timing.accelerationScale);
  }
  file.blendTolerance = timing.blendTolerance;
  file.trajectory = sampleTrajectory(*timing.timed, path.jointNames, options.sampleInterval);
  std::filesystem::path csv = output;
  csv.replace_extension(".csv");
  writeTrajectoryFile(output, file);
  writeTrajectoryCsv(csv, file.trajectory);
  char summary[512];
  std::snprintf(summary, sizeof summary,
                "  trajectory: %.3f s, %zu points every %g s, blend tolerance %g rad (%d attempt%s, %ld blend states "
                "checked) -> %s and %s\n",
                timing.timed->duration(), file.trajectory.points.size(), options.sampleInterval, timing.blendTolerance,
                timing.attempts, timing.attempts == 1 ? "" : "s", timing.statesChecked, output.string().c_str(),
                csv.string().c_str());
  return summary;
}

}  // namespace pmdplan::cli
