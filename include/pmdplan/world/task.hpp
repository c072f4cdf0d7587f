#pragma once
// A planning task: the robot and where it stands, the static obstacles, start and goal.
// Read from the task YAML schema of data/scenes/*.yaml (see docs in README).
#include <Eigen/Geometry>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/model/collision_shape.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct Obstacle {
  std::string name;
  Shape shape;                                             ///< mesh paths resolved to absolute
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< in the world frame
};

struct Task {
  std::filesystem::path file;  ///< where it was read from (empty if built in code)
  std::string name;
  std::string description;
  std::shared_ptr<const RobotModel> robot;
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  ///< robot root link in the world
  std::optional<std::string> target;                       ///< name of an obstacle the goal grasps
  std::vector<Obstacle> obstacles;
  Configuration start;
  Configuration goal;
  /// Where the approach ends when the goal grasps the target (docs/grasp_goals.md): optional; when
  /// absent and the goal touches the target, the planner derives one by opening the goal hand.
  std::optional<Configuration> pregrasp;

  const Obstacle* findObstacle(const std::string& obstacleName) const;
};

/// The longest task name (bytes).
inline constexpr std::size_t kMaxTaskNameLength = 100;

/// Empty when `name` is a plain task name: 1 to kMaxTaskNameLength letters, digits, `_`, `-` and `.`,
/// not starting with `.` (a name is printed and may name files, so no path, control character or
/// terminal escape). Otherwise what is wrong, showing the offending character escaped and the
/// name only by its length. The task reader and Python's Task apply it.
std::string taskNameProblem(const std::string& name);

/// Reads and validates a task file. Every problem is an InputError naming the file and the key:
/// a name that is not plain (taskNameProblem), unknown keys, missing or duplicated joints, values outside the limits,
/// NaN, unknown obstacle types, missing mesh files, an unloadable robot. The field reads like
/// `obstacles[2].cylinder.radius (line 14)`. Optional keys: description, fixed (joints held still, as start/goal but
/// any subset), target, pregrasp (a configuration like start and goal; only with a target), rpy_deg (of base and
/// obstacles, default 0 0 0) and mesh scale (default 1 1 1); `obstacles` may be []. `robot` is a built-in name unless
/// it has a directory part or ends in .urdf (then relative to the task file, with the .srdf of the same stem beside it
/// if present). Degrees are converted at load; a value that misses a joint limit by at most 1e-9 rad is taken as the
/// limit, anything further out is an error.
Task loadTask(const std::filesystem::path& file);

/// Gives the built-in robot of that name (data/robots/<name>/, known to exist) for a task.
using BuiltInRobotLoader = std::function<std::shared_ptr<const RobotModel>(const std::string& name)>;

/// As loadTask(file), with built-in robots from `loadBuiltInRobot` instead of loading each from its
/// files (RobotModel::loadBuiltIn): for a caller that reads many tasks and keeps the robots it
/// loaded once, as the task fuzzer does (fuzz/task_fuzzer.cpp).
Task loadTask(const std::filesystem::path& file, const BuiltInRobotLoader& loadBuiltInRobot);

/// A built-in task name (data/scenes/<name>.yaml) or a path.
Task loadTaskByName(const std::string& nameOrPath);

}  // namespace pmdplan
