#pragma once
// Geometric primitives shared by robot links and environment obstacles (SI units).
#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace pmdplan {

struct BoxShape {
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< full extents along local x, y, z
};
struct CylinderShape {
  double radius = 0.0;
  double length = 0.0;  ///< along local z, centred on the origin
};
struct SphereShape {
  double radius = 0.0;
};
struct TriangleMesh;  // mesh_file.hpp

struct MeshShape {
  std::filesystem::path file;  ///< absolute, or as resolved by the loader
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  /// Its triangles, scaled (loadMeshShape); null until read.
  std::shared_ptr<const TriangleMesh> triangles;
};

using Shape = std::variant<BoxShape, CylinderShape, SphereShape, MeshShape>;

/// A shape placed in some frame (a link frame or the world).
struct PlacedShape {
  Shape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

/// The bounds every collision shape obeys, one rule for URDF collision geometry, task obstacles and
/// Python's Task (docs/robustness.md, "Limits enforced up front"). A robot cell is metres across:
/// both collision checkers (and FCL under them) were run at these bounds (tests/cli/
/// geometry_bounds_cli_test.cpp); far beyond them FCL's GJK crashed (a 1e300 m box) or never ended
/// (a 1e20 m sphere).
struct ShapeBounds {
  static constexpr double kMinLength = 1e-6;   ///< m: box sides, radii, cylinder lengths
  static constexpr double kMaxLength = 100.0;  ///< m: the same, and a mesh vertex's distance from its frame
  /// m: |x|, |y|, |z| of an obstacle's, the base's or a URDF origin's position (as joint limits,
  /// which are within +-1000 rad or m).
  static constexpr double kMaxPosition = 1000.0;
  static constexpr double kMinMeshScale = 1e-6;  ///< each mesh scale factor (0.001: millimetres to metres)
  static constexpr double kMaxMeshScale = 1e3;
};

/// What breaks ShapeBounds in a shape: `part` extends the shape's field (".box[1]",
/// ".cylinder.radius", ".sphere", ".mesh.scale[0]"), `message` says what is expected and what was given.
struct ShapeBoundsProblem {
  std::string part;
  std::string message;
};

/// The first number of `shape` outside ShapeBounds (NaN and infinities included), if any. A mesh's
/// scale is checked here; its vertices when it is read (readMeshFile).
std::optional<ShapeBoundsProblem> shapeBoundsProblem(const Shape& shape);

/// The first coordinate of `position` that is not finite or beyond ShapeBounds::kMaxPosition
/// (part "[i]"), if any.
std::optional<ShapeBoundsProblem> positionBoundsProblem(const Eigen::Vector3d& position);

/// Throw InputError(file, field + part, message) for the problems above.
void checkShapeBounds(const Shape& shape, const std::string& file, const std::string& field);
void checkPositionBounds(const Eigen::Vector3d& position, const std::string& file, const std::string& field);

/// Radius of the smallest origin-centred sphere that encloses the shape in its own frame
/// (meshes: their farthest vertex; +inf for a mesh whose triangles were not read).
double boundingRadius(const Shape& shape);

}  // namespace pmdplan
