#pragma once
// Reading a configuration (`start:` or `goal:`) given joint by joint. Internal to world/.
#include <string>
#include <utility>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {

/// `{joints_deg: {name: degrees, ...}}` or `{joints: {name: radians, ...}}`: every active joint of
/// `robot` exactly once, each finite and within its limits. Values that miss a limit by at most
/// kJointLimitTolerance are taken as the limit itself (rounding of degree conversions, not user
/// error); anything further out is an error.
Configuration readJointValues(const YamlField& field, const RobotModel& robot);

/// The task's `fixed:` entry, in the same form, naming only the joints to hold (any subset of the
/// active joints of the URDF as loaded, each within its limits): joint name and value (rad or m).
std::vector<std::pair<std::string, double>> readHeldJointValues(const YamlField& field, const RobotModel& robot);

inline constexpr double kJointLimitTolerance = 1e-9;  ///< rad (or m for prismatic joints)

}  // namespace pmdplan
