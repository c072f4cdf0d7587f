#include "placement_reading.hpp"

#include <numbers>

namespace pmdplan {

Eigen::Matrix3d rotationFromRollPitchYaw(const Eigen::Vector3d& rollPitchYaw) {
  return (Eigen::AngleAxisd(rollPitchYaw.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rollPitchYaw.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rollPitchYaw.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d readPlacement(const YamlField& map) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = map.child("xyz", "a position [x, y, z] in metres").vector3("a position [x, y, z] in metres");
  if (const auto rpy = map.optionalChild("rpy_deg")) {
    const Eigen::Vector3d degrees = rpy->vector3("fixed-axis angles [roll, pitch, yaw] in degrees");
    pose.linear() = rotationFromRollPitchYaw(degrees * (std::numbers::pi / 180.0));
  }
  return pose;
}

}  // namespace pmdplan
