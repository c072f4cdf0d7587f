#include "trajectory_output.hpp"

#include <cstdio>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/trajectory/collision_free_timing.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"
#include "pmdplan/trajectory/joint_trajectory.hpp"

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

std::filesystem::path trajectoryCsvFile(const std::filesystem::path& output) {
  return std::filesystem::path(output).replace_extension(".csv");
}

void checkTrajectoryOutputs(const Task& task, const TrajectoryOutputOptions& options,
                            const std::filesystem::path& output, const std::string& option) {
  checkTimingOptions(options);
  jointMotionLimits(*task.robot, options.jointLimits.empty()
                                     ? std::nullopt
                                     : std::optional<std::filesystem::path>(options.jointLimits));
  checkOutputPath(output, option);
  checkOutputPath(trajectoryCsvFile(output), option + " (its CSV)");
}

namespace {

/// Runs `check`, giving an InputError from the library the option's name ("blend-tolerance" ->
/// "--blend-tolerance"; the duration bound names the scales that set it).
template <typename Check>
void withOptionNames(const Check& check) {
  try {
    check();
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError("", e.field() == "duration" ? "--velocity-scale, --acceleration-scale" : "--" + e.field(),
                     e.message());
  }
}

}  // namespace

void checkTimingOptions(const TrajectoryOutputOptions& options) {
  withOptionNames([&] {
    options.timing.check();
    checkSampling(0.0, options.sampleInterval);
  });
}

std::string writeTimedTrajectory(const Task& task, CollisionChecking& checking, const PathFile& path,
                                 const TrajectoryOutputOptions& options, const std::filesystem::path& output) {
  checkTimingOptions(options);
  const auto limits = jointMotionLimits(*task.robot, options.jointLimits.empty()
                                                         ? std::nullopt
                                                         : std::optional<std::filesystem::path>(options.jointLimits));
  // The work, bounded before it starts: the integration by the path's rest-to-rest duration, the
  // samples by the same duration with a margin (the blended timing takes up to a few percent longer).
  withOptionNames([&] {
    checkTimingWork(path.points, limits, options.timing);
    checkSampling(1.1 * restToRestDuration(path.points, limits, options.timing), options.sampleInterval);
  });
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
  const std::filesystem::path csv = trajectoryCsvFile(output);
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
