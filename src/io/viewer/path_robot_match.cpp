#include "pmdplan/io/viewer/path_robot_match.hpp"

#include <cmath>
#include <map>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

constexpr double kLimitTolerance = 1e-9;

std::string joinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

/// For each active joint of the robot, its column in the file; InputError if the sets differ.
std::vector<std::size_t> columnsOfRobotJoints(const PathFile& path, const RobotModel& robot, const std::string& file) {
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < path.jointNames.size(); ++i) column.emplace(path.jointNames[i], i);
  std::vector<std::string> missing, unknown;
  std::vector<std::size_t> columns;
  for (const auto& name : robot.activeJointNames()) {
    const auto found = column.find(name);
    if (found == column.end())
      missing.push_back(name);
    else
      columns.push_back(found->second);
  }
  for (const auto& name : path.jointNames)
    if (robot.activeIndex(name) < 0) unknown.push_back(name);
  if (missing.empty() && unknown.empty()) return columns;
  std::string message = "expected the " + std::to_string(robot.dof()) + " active joints of robot '" + robot.name() +
                        "', found " + std::to_string(path.jointNames.size()) + " names";
  if (!unknown.empty()) message += "; not joints of the robot: " + joinNames(unknown);
  if (!missing.empty()) message += "; missing: " + joinNames(missing);
  message += " (was the path planned for another robot?)";
  throw InputError(file, "joint_names", message);
}

void checkMimic(const PathFile& path, const RobotModel& robot, const std::string& file) {
  std::map<std::string, MimicRelation> expected;
  for (auto& relation : mimicRelations(robot)) expected.emplace(relation.joint, relation);
  for (const MimicRelation& relation : path.mimic) {
    const std::string field = "mimic." + relation.joint;
    const auto found = expected.find(relation.joint);
    if (found == expected.end())
      throw InputError(file, field, "robot '" + robot.name() + "' has no coupled joint of this name");
    const MimicRelation& want = found->second;
    if (relation.source != want.source || std::abs(relation.multiplier - want.multiplier) > 1e-12 ||
        std::abs(relation.offset - want.offset) > 1e-12)
      throw InputError(file, field,
                       "expected [\"" + want.source + "\", " + messageNumberText(want.multiplier) + ", " +
                           messageNumberText(want.offset) + "] as in robot '" + robot.name() + "', found [\"" +
                           relation.source + "\", " + messageNumberText(relation.multiplier) + ", " +
                           messageNumberText(relation.offset) + "]");
    expected.erase(found);
  }
  if (!expected.empty()) {
    std::vector<std::string> left;
    for (const auto& [name, relation] : expected) left.push_back(name);
    throw InputError(file, "mimic",
                     "robot '" + robot.name() + "' couples joints the file leaves out: " + joinNames(left));
  }
}

}  // namespace

std::vector<Configuration> pathConfigurations(const PathFile& path, const RobotModel& robot, const std::string& file) {
  const std::vector<std::size_t> columns = columnsOfRobotJoints(path, robot, file);
  checkMimic(path, robot, file);
  const JointLimits& limits = robot.activeJoints();
  std::vector<Configuration> configurations;
  configurations.reserve(path.points.size());
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    Configuration q(robot.dof());
    for (std::size_t j = 0; j < columns.size(); ++j) {
      const double value = path.points[i][static_cast<Eigen::Index>(columns[j])];
      const JointLimit& limit = limits[j];
      if (value < limit.lower - kLimitTolerance || value > limit.upper + kLimitTolerance)
        throw InputError(file, "points[" + std::to_string(i) + "].positions[" + std::to_string(columns[j]) + "]",
                         limit.name + " = " + messageNumberText(value) + " is outside its limits [" +
                             messageNumberText(limit.lower) + ", " + messageNumberText(limit.upper) + "] (rad)");
      q[static_cast<Eigen::Index>(j)] = value;
    }
    configurations.push_back(std::move(q));
  }
  return configurations;
}

}  // namespace pmdplan
