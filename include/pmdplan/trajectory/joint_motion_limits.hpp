#pragma once
// How fast each active joint may move: the velocity from the URDF's <limit velocity>, the
// acceleration from the robot's joint-limits file (`<robot>.joint_limits.yaml` beside its URDF,
// MoveIt's joint_limits.yaml shape), and a mimic joint's own limits folded into its source's
// (a mimic joint moving `multiplier` times as fast as its source bounds the source by
// limit / |multiplier|).
//
//   joint_limits:
//     tx90_joint_1: {max_acceleration: 13.96}     rad/s² (m/s² for prismatic joints)
//     thumb_base: {max_velocity: 3.14, max_acceleration: 6.28}   max_velocity only lowers the URDF's
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct JointMotionLimit {
  std::string name;
  double velocity = 0.0;      ///< rad/s (m/s)
  double acceleration = 0.0;  ///< rad/s² (m/s²)
};

/// Limits used when neither the URDF nor the joint-limits file gives one.
struct JointMotionDefaults {
  /// A joint whose URDF <limit> has no (or a zero) velocity: 1 rad/s.
  double velocity = 1.0;
  /// A joint with no max_acceleration: full speed reached in half a second, a = 2 s⁻¹ · velocity.
  double accelerationPerVelocity = 2.0;
};

/// The joint-limits file MoveIt-style robots keep beside the URDF: `<urdf stem>.joint_limits.yaml`.
std::filesystem::path jointLimitsFileFor(const RobotModel& robot);

/// One entry per active joint, in configuration order, every value positive and finite. `file`
/// defaults to jointLimitsFileFor(robot) when that exists; an explicit file must exist. Throws
/// InputError naming the file and key for unknown joints or keys, and values that are not positive.
std::vector<JointMotionLimit> jointMotionLimits(const RobotModel& robot,
                                                const std::optional<std::filesystem::path>& file = std::nullopt,
                                                const JointMotionDefaults& defaults = {});

}  // namespace pmdplan
