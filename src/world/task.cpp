#include "pmdplan/world/task.hpp"

#include <cstdio>

#include "joint_values_reading.hpp"
#include "obstacle_reading.hpp"
#include "placement_reading.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {
namespace {

constexpr const char* kRobotForm =
    "a built-in robot name (data/robots/<name>/) or a .urdf file: a path relative to the task "
    "file, file:///path or package://NAME/path";

/// `robot:` names a built-in robot unless it looks like a path (has a directory part or ends in
/// .urdf); a URDF path uses the SRDF of the same stem beside it when there is one.
std::shared_ptr<const RobotModel> readRobot(const YamlField& field, const std::filesystem::path& taskDirectory,
                                            const BuiltInRobotLoader& loadBuiltInRobot) {
  const std::string written = field.text(kRobotForm);
  if (written.empty()) field.fail(std::string("expected ") + kRobotForm + ", got an empty string");
  const std::filesystem::path asPath = written;
  if (asPath.has_parent_path() || asPath.extension() == ".urdf") {
    std::filesystem::path urdf;
    try {
      urdf = resolveResourcePath(written, taskDirectory / "task", "robot");
    } catch (const InputError& e) {
      field.fail("URDF file not found: " + e.message() + " (a relative path is relative to the task file)");
    }
    std::error_code error;
    std::optional<std::filesystem::path> srdf;
    if (auto candidate = std::filesystem::path(urdf).replace_extension(".srdf");
        std::filesystem::is_regular_file(candidate, error)) {
      srdf = candidate;
    }
    return std::make_shared<const RobotModel>(RobotModel::load(urdf, srdf));
  }
  const auto builtIn = dataDirectory() / "robots" / written / (written + ".urdf");
  std::error_code error;
  if (!std::filesystem::is_regular_file(builtIn, error)) {
    field.fail("unknown built-in robot '" + written + "' (no " + builtIn.string() + "); expected " + kRobotForm);
  }
  return loadBuiltInRobot(written);
}

}  // namespace

std::string taskNameProblem(const std::string& name) {
  const std::string form =
      "expected a plain task name (letters, digits, '_', '-' and '.', not starting with '.', at most " +
      std::to_string(kMaxTaskNameLength) + " characters)";
  if (name.empty()) return form + ", got an empty one";
  if (name.size() > kMaxTaskNameLength) return form + ", got a name of " + std::to_string(name.size()) + " characters";
  if (name.front() == '.') return form + ", got a name starting with '.'";
  for (std::size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.')
      continue;
    char shown[8];
    if (c > 0x20 && c < 0x7f)
      std::snprintf(shown, sizeof shown, "'%c'", c);
    else
      std::snprintf(shown, sizeof shown, "\\x%02X", c);
    return form + ", got a name of " + std::to_string(name.size()) + " characters with " + shown + " at character " +
           std::to_string(i + 1);
  }
  return "";
}

const Obstacle* Task::findObstacle(const std::string& obstacleName) const {
  for (const Obstacle& obstacle : obstacles) {
    if (obstacle.name == obstacleName) return &obstacle;
  }
  return nullptr;
}

Task loadTask(const std::filesystem::path& file) {
  return loadTask(
      file, [](const std::string& name) { return std::make_shared<const RobotModel>(RobotModel::loadBuiltIn(name)); });
}

Task loadTask(const std::filesystem::path& file, const BuiltInRobotLoader& loadBuiltInRobot) {
  const std::string fileName = file.string();
  const std::string text = readTextFile(file);
  const YamlField root(fileName, parseYamlDocument(text, fileName));
  const std::filesystem::path taskDirectory = std::filesystem::absolute(file).parent_path();

  root.requireMapWithKeys(
      {"name", "description", "robot", "base", "fixed", "target", "obstacles", "start", "goal", "pregrasp"},
      "a task map");
  Task task;
  task.file = file;
  const YamlField nameField = root.child("name", "the task name");
  task.name = nameField.text("the task name");
  if (const std::string problem = taskNameProblem(task.name); !problem.empty()) nameField.fail(problem);
  if (const auto description = root.optionalChild("description")) {
    task.description = description->text("a one-line description");
  }
  task.robot = readRobot(root.child("robot", kRobotForm), taskDirectory, loadBuiltInRobot);
  if (const auto fixed = root.optionalChild("fixed")) {
    const auto held = readHeldJointValues(*fixed, *task.robot);
    task.robot = std::make_shared<const RobotModel>(task.robot->withHeldJoints(held, "fixed"));
  }

  const std::string baseForm = "the robot base pose {xyz: [x, y, z] m, rpy_deg: [r, p, y]}";
  const YamlField base = root.child("base", baseForm);
  base.requireMapWithKeys({"xyz", "rpy_deg"}, baseForm);
  task.base = readPlacement(base);

  task.obstacles = readObstacles(root.child("obstacles", "a list of obstacles (may be [])"), taskDirectory);
  if (const auto target = root.optionalChild("target")) {
    const std::string name = target->text("the name of an obstacle");
    if (!task.findObstacle(name)) {
      std::string names;
      for (const auto& obstacle : task.obstacles) names += (names.empty() ? "" : ", ") + obstacle.name;
      target->fail("'" + name +
                   "' names no obstacle; expected one of: " + (names.empty() ? std::string("(no obstacles)") : names));
    }
    task.target = name;
  }
  const std::string configurationForm = "{joints_deg: {...}} or {joints: {...}}";
  task.start = readJointValues(root.child("start", configurationForm), *task.robot);
  task.goal = readJointValues(root.child("goal", configurationForm), *task.robot);
  if (const auto pregrasp = root.optionalChild("pregrasp")) {
    if (!task.target)
      pregrasp->fail("a pregrasp needs the task's target (the obstacle the goal grasps): add `target:`");
    task.pregrasp = readJointValues(*pregrasp, *task.robot);
  }
  return task;
}

Task loadTaskByName(const std::string& nameOrPath) { return loadTask(resolveTaskPath(nameOrPath)); }

}  // namespace pmdplan
