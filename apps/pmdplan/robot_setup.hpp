#pragma once
// What `pmdplan robot init` and `pmdplan collision-pairs` share: a robot loaded with a companion
// text that is not a file yet, and the home pose written on the command line.
#include <string>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan::cli {

/// The URDF with `companionText` as its SRDF (through a scratch file, removed again).
RobotModel loadWithCompanionText(const std::filesystem::path& urdf, const std::string& companionText);

/// `NAME=DEG,NAME=DEG,...` (degrees; metres for prismatic joints): the named active joints at those
/// values, every other active joint at 0 or, if 0 is outside its limits, its nearest limit (as
/// MoveIt Setup Assistant's default pose). Errors name `--home`.
Configuration homeConfiguration(const RobotModel& model, const std::string& text);

/// The command that writes an SRDF for `urdf`, for error messages.
std::string robotInitHint(const std::filesystem::path& urdf);

}  // namespace pmdplan::cli
