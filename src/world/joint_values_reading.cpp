#include "joint_values_reading.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

std::string listNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

bool isPrismatic(const RobotModel& robot, const std::string& jointName) {
  const int index = robot.jointIndex(jointName);
  return index >= 0 && robot.joints()[static_cast<std::size_t>(index)].type == JointType::Prismatic;
}

/// The values given, by active index; with `every`, each active joint must appear.
std::vector<std::pair<int, double>> readValues(const YamlField& field, const RobotModel& robot, bool every) {
  const std::string form =
      std::string("{joints_deg: {joint: degrees, ...}} or {joints: {joint: radians, ...}} listing ") +
      (every ? "every active joint once" : "the joints to hold");
  field.requireMapWithKeys({"joints_deg", "joints"}, form);
  const bool inDegrees = field.has("joints_deg");
  if (inDegrees && field.has("joints")) {
    field.child("joints", form).fail("give either joints_deg or joints, not both");
  }
  const YamlField values = field.child(inDegrees ? "joints_deg" : "joints", form);
  const std::string unit = inDegrees ? "deg" : "rad";
  const double toInternal = inDegrees ? std::numbers::pi / 180.0 : 1.0;

  const JointLimits& limits = robot.activeJoints();
  std::vector<std::pair<int, double>> out;
  std::vector<bool> given(limits.size(), false);
  const std::string mapForm = "a map {joint name: value in " + unit + "}";
  for (const auto& [name, value] : values.mapEntries(mapForm)) {
    const int index = robot.activeIndex(name);
    if (index < 0) {
      const int jointIndex = robot.jointIndex(name);
      if (jointIndex >= 0) {
        const Joint& joint = robot.joints()[static_cast<std::size_t>(jointIndex)];
        if (joint.mimicSource >= 0) {
          value.fail(
              "'" + name + "' follows " + robot.joints()[static_cast<std::size_t>(joint.mimicSource)].name +
              " (mimic) and is derived from it; list only active joints: " + listNames(robot.activeJointNames()));
        }
        if (robot.heldJointValue(name))
          value.fail("'" + name + "' is held by the task's `fixed:` entry; list only active joints: " +
                     listNames(robot.activeJointNames()));
        value.fail("'" + name + "' is a fixed joint; list only active joints: " + listNames(robot.activeJointNames()));
      }
      value.fail("unknown joint '" + name + "' for robot " + robot.name() +
                 "; its active joints are: " + listNames(robot.activeJointNames()));
    }
    const auto slot = static_cast<std::size_t>(index);
    if (inDegrees && isPrismatic(robot, name)) {
      value.fail("prismatic joint: give its value in metres under `joints`, not in degrees");
    }
    const JointLimit& limit = limits[slot];
    const std::string range =
        messageNumberText(limit.lower / toInternal) + " .. " + messageNumberText(limit.upper / toInternal) + " " + unit;
    double internal = value.number("a joint value in " + unit + " within " + range) * toInternal;
    if (internal < limit.lower - kJointLimitTolerance || internal > limit.upper + kJointLimitTolerance) {
      value.fail(messageNumberText(internal / toInternal) + " " + unit + " is outside the joint limits " + range);
    }
    // Degree values written at a limit convert to within rounding of it: keep them exactly on it,
    // so that normalised coordinates stay inside [0, 1].
    internal = std::clamp(internal, limit.lower, limit.upper);
    given[slot] = true;
    out.emplace_back(index, internal);
  }
  if (!every) return out;
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < limits.size(); ++i) {
    if (!given[i]) missing.push_back(limits[i].name);
  }
  if (!missing.empty()) {
    values.fail("missing joint" + std::string(missing.size() > 1 ? "s " : " ") + listNames(missing) +
                "; every active joint appears exactly once (joints the task keeps still "
                "go under `fixed: {joints_deg: {...}}` instead)");
  }
  return out;
}

}  // namespace

Configuration readJointValues(const YamlField& field, const RobotModel& robot) {
  Configuration q(robot.dof());
  for (const auto& [index, value] : readValues(field, robot, true)) q[index] = value;
  return q;
}

std::vector<std::pair<std::string, double>> readHeldJointValues(const YamlField& field, const RobotModel& robot) {
  std::vector<std::pair<std::string, double>> held;
  for (const auto& [index, value] : readValues(field, robot, false))
    held.emplace_back(robot.activeJoints()[static_cast<std::size_t>(index)].name, value);
  return held;
}

}  // namespace pmdplan
