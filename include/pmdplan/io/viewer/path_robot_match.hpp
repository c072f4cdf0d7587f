#pragma once
// A path file checked against the robot it is meant for, before anything draws or replays it:
// a path planned for another robot (or another version of it) must fail with a clear message,
// not show a broken animation.
#include <string>
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

/// The path's points as configurations of `robot` (its active-joint order; the file may list the
/// same joints in another order). Throws InputError naming `file` and the key: `joint_names` that
/// are not exactly the robot's active joints (which are missing, which are unknown),
/// `points[i].positions[k]` outside the joint's limits by more than 1e-9, and `mimic` entries that
/// differ from the robot's couplings (a joint the robot does not couple, another source,
/// multiplier or offset, a coupled joint left out).
std::vector<Configuration> pathConfigurations(const PathFile& path, const RobotModel& robot, const std::string& file);

}  // namespace pmdplan
