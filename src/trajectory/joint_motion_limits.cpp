#include "pmdplan/trajectory/joint_motion_limits.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/yaml_input.hpp"

namespace pmdplan {
namespace {

struct FileLimit {
  std::optional<double> velocity;
  std::optional<double> acceleration;
};

double positive(const YAML::Node& node, const std::string& file, const std::string& key) {
  const double value = yaml_input::number(node, file, key);
  if (!(std::isfinite(value) && value > 0.0)) throw InputError(file, key, "expected a positive number");
  return value;
}

std::map<std::string, FileLimit> readLimitsFile(const RobotModel& robot, const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "", "cannot open the joint-limits file");
  std::stringstream text;
  text << in.rdbuf();
  const std::string file = path.string();
  const YAML::Node root = yaml_input::parseDocument(text.str(), file);
  yaml_input::expectMap(root, file, "the document");
  yaml_input::rejectUnknownKeys(root, {"joint_limits"}, file, "the document");
  const YAML::Node joints = yaml_input::required(root, "joint_limits", file, "the document");
  yaml_input::expectMap(joints, file, "joint_limits");
  std::map<std::string, FileLimit> limits;
  for (const auto& entry : joints) {
    const std::string name = yaml_input::text(entry.first, file, "joint_limits");
    const std::string key = "joint_limits." + name;
    if (robot.jointIndex(name) < 0 ||
        robot.joints()[static_cast<std::size_t>(robot.jointIndex(name))].type == JointType::Fixed)
      throw InputError(file, key, "'" + name + "' is not a moving joint of robot " + robot.name());
    yaml_input::expectMap(entry.second, file, key);
    yaml_input::rejectUnknownKeys(entry.second, {"max_velocity", "max_acceleration"}, file, key);
    FileLimit limit;
    if (entry.second["max_velocity"])
      limit.velocity = positive(entry.second["max_velocity"], file, key + ".max_velocity");
    if (entry.second["max_acceleration"])
      limit.acceleration = positive(entry.second["max_acceleration"], file, key + ".max_acceleration");
    limits[name] = limit;
  }
  return limits;
}

}  // namespace

std::filesystem::path jointLimitsFileFor(const RobotModel& robot) {
  std::filesystem::path file = robot.urdfPath();
  return file.replace_extension(".joint_limits.yaml");
}

std::vector<JointMotionLimit> jointMotionLimits(const RobotModel& robot,
                                                const std::optional<std::filesystem::path>& file,
                                                const JointMotionDefaults& defaults) {
  std::map<std::string, FileLimit> fromFile;
  if (file) {
    fromFile = readLimitsFile(robot, *file);
  } else if (const auto beside = jointLimitsFileFor(robot);
             !robot.urdfPath().empty() && std::filesystem::exists(beside)) {
    fromFile = readLimitsFile(robot, beside);
  }
  const auto own = [&](const Joint& joint) {
    JointMotionLimit limit{joint.name, joint.velocity > 0.0 ? joint.velocity : defaults.velocity, 0.0};
    const auto found = fromFile.find(joint.name);
    if (found != fromFile.end() && found->second.velocity)
      limit.velocity = std::min(limit.velocity, *found->second.velocity);
    limit.acceleration = found != fromFile.end() && found->second.acceleration
                             ? *found->second.acceleration
                             : defaults.accelerationPerVelocity * limit.velocity;
    return limit;
  };
  std::vector<JointMotionLimit> limits(static_cast<std::size_t>(robot.dof()));
  for (const Joint& joint : robot.joints())
    if (joint.activeIndex >= 0) limits[static_cast<std::size_t>(joint.activeIndex)] = own(joint);
  for (const Joint& joint : robot.joints()) {
    if (joint.mimicSource < 0 || joint.mimicMultiplier == 0.0) continue;
    int source = joint.mimicSource;
    double multiplier = joint.mimicMultiplier;
    while (robot.joints()[static_cast<std::size_t>(source)].mimicSource >= 0) {
      const Joint& next = robot.joints()[static_cast<std::size_t>(source)];
      multiplier *= next.mimicMultiplier;
      source = next.mimicSource;
    }
    const int active = robot.joints()[static_cast<std::size_t>(source)].activeIndex;
    if (active < 0 || multiplier == 0.0) continue;
    const JointMotionLimit mimic = own(joint);
    JointMotionLimit& target = limits[static_cast<std::size_t>(active)];
    target.velocity = std::min(target.velocity, mimic.velocity / std::abs(multiplier));
    target.acceleration = std::min(target.acceleration, mimic.acceleration / std::abs(multiplier));
  }
  return limits;
}

}  // namespace pmdplan
