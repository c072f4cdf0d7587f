#pragma once
// Reading where a thing stands: `xyz` in metres and an optional `rpy_deg` with URDF's fixed-axis
// convention. Internal to world/.
#include <Eigen/Geometry>
#include <optional>

#include "pmdplan/model/collision_shape.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan {

/// URDF's fixed-axis roll, pitch, yaw (radians): R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d rotationFromRollPitchYaw(const Eigen::Vector3d& rollPitchYaw);

/// The pose given by the `xyz` (required; each coordinate within ShapeBounds::kMaxPosition) and
/// `rpy_deg` (optional, default 0 0 0) keys of a map. The caller checks which other keys the map may hold.
Eigen::Isometry3d readPlacement(const YamlField& map);

/// Throws a problem found by shapeBoundsProblem or positionBoundsProblem as the InputError of
/// `field`'s path extended by the problem's part (`obstacles[2]` + `.box[1]`), at `field`'s line.
void failOnBoundsProblem(const YamlField& field, const std::optional<ShapeBoundsProblem>& problem);

}  // namespace pmdplan
