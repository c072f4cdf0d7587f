#include "pmdplan/trajectory/joint_motion_limits.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {
namespace {

struct FileLimit {
  std::optional<double> velocity;
  std::optional<double> acceleration;
};

std::map<std::string, FileLimit> readLimitsFile(const RobotModel& robot, const std::filesystem::path& path) {
  const YamlField root(path.string(), parseYamlDocument(readTextFile(path), path.string()));
  root.requireMapWithKeys({"joint_limits"}, "a joint-limits file");
  std::map<std::string, FileLimit> limits;
  for (const auto& [name, entry] : root.child("joint_limits", "a map of joint names").mapEntries("a map of joints")) {
    const int index = robot.jointIndex(name);
    if (index < 0 || robot.joints()[static_cast<std::size_t>(index)].type == JointType::Fixed)
      entry.fail("'" + name + "' is not a moving joint of robot " + robot.name());
    entry.requireMapWithKeys({"max_velocity", "max_acceleration"}, "{max_velocity, max_acceleration}");
    FileLimit limit;
    if (const auto velocity = entry.optionalChild("max_velocity"))
      limit.velocity = velocity->positiveNumber("a positive velocity");
    if (const auto acceleration = entry.optionalChild("max_acceleration"))
      limit.acceleration = acceleration->positiveNumber("a positive acceleration");
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
