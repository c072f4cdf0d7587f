#pragma once
// The timed trajectory `pmdplan time` and `pmdplan plan --trajectory` write: the path timed
// optimally under the robot's joint limits, its blends checked with the task's checker, written as
// the trajectory JSON and, beside it, the same samples as CSV (F.json -> F.csv).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/trajectory/timed_path.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli {

struct TrajectoryOutputOptions {
  TimingSettings timing;
  std::string jointLimits;       ///< joint-limits YAML (default: the robot's, beside its URDF)
  double sampleInterval = 0.01;  ///< seconds between the written points
};

/// --blend-tolerance, --velocity-scale, --acceleration-scale, --joint-limits, --sample-interval.
void addTrajectoryOptions(CLI::App& app, TrajectoryOutputOptions& options);

/// The timing options' ranges (TimingSettings::check, checkSampling): InputError naming the option.
void checkTimingOptions(const TrajectoryOutputOptions& options);

/// TASK.path.json -> TASK.trajectory.json beside it.
std::filesystem::path defaultTrajectoryFile(const std::filesystem::path& pathFile);

/// F.json -> F.csv: the CSV written beside a trajectory file.
std::filesystem::path trajectoryCsvFile(const std::filesystem::path& output);

/// Before the work: reads the joint limits the timing will use (so they count as inputs) and
/// checks `output` and its CSV as outputs of `option` (core/atomic_file.hpp).
void checkTrajectoryOutputs(const Task& task, const TrajectoryOutputOptions& options,
                            const std::filesystem::path& output, const std::string& option);

/// Times `path`, writes `output` and its CSV; returns a line to print (duration, blends, checks).
std::string writeTimedTrajectory(const Task& task, CollisionChecking& checking, const PathFile& path,
                                 const TrajectoryOutputOptions& options, const std::filesystem::path& output);

}  // namespace pmdplan::cli
