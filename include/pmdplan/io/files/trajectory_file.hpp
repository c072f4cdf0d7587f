#pragma once
// The trajectory file (`pmdplan plan --trajectory`, `pmdplan time`): a timed path shaped like
// ROS's trajectory_msgs/JointTrajectory, with what produced it.
//
//   {
//     "format": "pmdplan-joint-trajectory", "version": 1,
//     "task": "can_on_table", "planner": "pmd", "seed": 1,
//     "joint_names": ["a1", ...],                              active joints, configuration order
//     "mimic": {"index_distal": ["index_medium", 1, 0], ...},  as in the path file
//     "limits": {"velocity": [...], "acceleration": [...]},    per joint, as used (scales applied)
//     "blend_tolerance": 0.01, "duration": 2.345,
//     "points": [{"positions": [...], "velocities": [...], "accelerations": [...],
//                 "time_from_start": 0.01}, ...]               rad, rad/s, rad/s², s
//   }
//
// Same bytes for the same inputs (formatJson). The CSV has a header `time_from_start`, then each
// joint's position, then `<joint>.velocity` and `<joint>.acceleration` columns.
#include <filesystem>
#include <string>
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/trajectory/joint_trajectory.hpp"

namespace pmdplan {

struct TrajectoryFile {
  std::string task;
  std::string planner;
  std::uint64_t seed = 0;
  std::vector<MimicRelation> mimic;
  std::vector<double> velocityLimits;
  std::vector<double> accelerationLimits;
  double blendTolerance = 0.0;
  JointTrajectory trajectory;
};

/// Throws std::invalid_argument for points of the wrong size or values that are not finite.
std::string formatTrajectoryFile(const TrajectoryFile& file);
std::string formatTrajectoryCsv(const JointTrajectory& trajectory);
void writeTrajectoryFile(const std::filesystem::path& path, const TrajectoryFile& file);
void writeTrajectoryCsv(const std::filesystem::path& path, const JointTrajectory& trajectory);

/// Whether the text is a trajectory file (its "format" says so), not a path file.
bool isTrajectoryFileText(const std::string& text);
/// Every problem an InputError naming `file` and the key: wrong types or sizes, unknown keys,
/// fewer than two points, times not increasing.
TrajectoryFile parseTrajectoryFile(const std::string& text, const std::string& file);

}  // namespace pmdplan
