#include "pmdplan/synergy/synergy_model_resolution.hpp"

#include <system_error>

#include "pmdplan/synergy/hand_fit.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

namespace pmdplan {

ResolvedSynergyModel resolveSynergyModel(const std::string& robotName, const std::filesystem::path& given,
                                         SynergyModelNeed need) {
  ResolvedSynergyModel resolved;
  if (!given.empty()) {
    resolved.file = given;
  } else if (need == SynergyModelNeed::Required) {
    resolved.file = shippedSynergyModelPath(robotName);  // throws, explaining, when the robot ships none
  } else {
    std::error_code error;
    const auto shipped = defaultSynergyModelPath(robotName);
    if (!std::filesystem::exists(shipped, error)) return resolved;
    resolved.file = shipped;
  }
  resolved.model = loadSynergyModel(resolved.file);
  return resolved;
}

ResolvedSynergyModel resolveSynergyModelForHand(const RobotModel& robot, const std::filesystem::path& given,
                                                SynergyModelNeed need) {
  ResolvedSynergyModel resolved = resolveSynergyModel(robot.name(), given, need);
  if (!resolved.model) return resolved;
  std::vector<std::string> handJoints;
  const std::vector<std::string> names = robot.activeJointNames();
  if (robot.hasGroup("hand"))
    for (const int i : robot.group("hand")) handJoints.push_back(names[static_cast<std::size_t>(i)]);
  checkSynergyModelFitsHand(*resolved.model, handJoints, resolved.file.string());
  return resolved;
}

}  // namespace pmdplan
