#include "placement_reading.hpp"

#include <numbers>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

Eigen::Matrix3d rotationFromRollPitchYaw(const Eigen::Vector3d& rollPitchYaw) {
  return (Eigen::AngleAxisd(rollPitchYaw.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rollPitchYaw.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rollPitchYaw.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d readPlacement(const YamlField& map) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const YamlField xyz = map.child("xyz", "a position [x, y, z] in metres");
  pose.translation() = xyz.vector3("a position [x, y, z] in metres");
  failOnBoundsProblem(xyz, positionBoundsProblem(pose.translation()));
  if (const auto rpy = map.optionalChild("rpy_deg")) {
    const Eigen::Vector3d degrees = rpy->vector3("fixed-axis angles [roll, pitch, yaw] in degrees");
    pose.linear() = rotationFromRollPitchYaw(degrees * (std::numbers::pi / 180.0));
  }
  return pose;
}

void failOnBoundsProblem(const YamlField& field, const std::optional<ShapeBoundsProblem>& problem) {
  if (!problem) return;
  std::string where = field.path() + problem->part;
  if (field.line() > 0) where += " (line " + std::to_string(field.line()) + ")";
  throw InputError(field.file(), where, problem->message);
}

}  // namespace pmdplan
