#pragma once
// Geometric primitives shared by robot links and environment obstacles (SI units).
#include <Eigen/Geometry>
#include <filesystem>
#include <memory>
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

/// Radius of the smallest origin-centred sphere that encloses the shape in its own frame
/// (meshes: their farthest vertex; +inf for a mesh whose triangles were not read).
double boundingRadius(const Shape& shape);

}  // namespace pmdplan
