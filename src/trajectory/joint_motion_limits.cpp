#include "pmdplan/trajectory/joint_motion_limits.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {
namespace {

struct FileLimit {
  std::optional<double> velocity;
  std::optional<double> acceleration;
};

/// A limit of a MoveIt-style entry: `max_<what>` applies unless `has_<what>_limits` is false (MoveIt
/// writes `has_acceleration_limits: false` with `max_acceleration: 0`, meaning none).
std::optional<double> limitOf(const YamlField& entry, const std::string& what, const std::string& expected) {
  const std::string flagKey = "has_" + what + "_limits", valueKey = "max_" + what;
  const auto flag = entry.optionalChild(flagKey);
  const auto value = entry.optionalChild(valueKey);
  if (flag && !flag->boolean(flagKey)) return std::nullopt;
  if (!value) {
    if (flag) entry.fail(flagKey + " is true but " + valueKey + " is missing");
    return std::nullopt;
  }
  return value->positiveNumber(expected);
}

/// MoveIt's joint_limits.yaml as moveit_setup_assistant writes it, or just the two limits we use.
/// Position, jerk and effort limits and the default scaling factors are read for their form only:
/// positions come from the URDF, the timing has no jerk or effort limit, and the speed scaling is
/// `pmdplan time`'s --velocity-scale / --acceleration-scale (docs/trajectories.md).
std::map<std::string, FileLimit> readLimitsFile(const RobotModel& robot, const std::filesystem::path& path) {
  const YamlField root(path.string(), parseYamlDocument(readTextFile(path), path.string()));
  root.requireMapWithKeys({"joint_limits", "default_velocity_scaling_factor", "default_acceleration_scaling_factor"},
                          "a joint-limits file");
  for (const char* factor : {"default_velocity_scaling_factor", "default_acceleration_scaling_factor"})
    if (const auto value = root.optionalChild(factor)) value->positiveNumber("a positive scaling factor");
  std::map<std::string, FileLimit> limits;
  for (const auto& [name, entry] : root.child("joint_limits", "a map of joint names").mapEntries("a map of joints")) {
    const int index = robot.jointIndex(name);
    if (index < 0 || robot.joints()[static_cast<std::size_t>(index)].type == JointType::Fixed)
      entry.fail(quotedText(name) + " is not a moving joint of robot " + robot.name());
    entry.requireMapWithKeys(
        {"has_velocity_limits", "max_velocity", "has_acceleration_limits", "max_acceleration", "has_position_limits",
         "min_position", "max_position", "has_jerk_limits", "max_jerk", "has_effort_limits", "max_effort"},
        "{max_velocity, max_acceleration} (MoveIt's joint_limits.yaml keys)");
    for (const char* flag : {"has_position_limits", "has_jerk_limits", "has_effort_limits"})
      if (const auto value = entry.optionalChild(flag)) value->boolean(flag);
    for (const char* number : {"min_position", "max_position", "max_jerk", "max_effort"})
      if (const auto value = entry.optionalChild(number)) value->number("a number");
    limits[name] = {limitOf(entry, "velocity", "a positive velocity"),
                    limitOf(entry, "acceleration", "a positive acceleration")};
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
