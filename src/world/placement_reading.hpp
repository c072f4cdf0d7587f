#pragma once
// Reading where a thing stands: `xyz` in metres and an optional `rpy_deg` with URDF's fixed-axis
// convention. Internal to world/.
#include <Eigen/Geometry>

#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {

/// URDF's fixed-axis roll, pitch, yaw (radians): R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d rotationFromRollPitchYaw(const Eigen::Vector3d& rollPitchYaw);

/// The pose given by the `xyz` (required) and `rpy_deg` (optional, default 0 0 0) keys of a map.
/// The caller checks which other keys the map may hold.
Eigen::Isometry3d readPlacement(const YamlField& map);

}  // namespace pmdplan
