#pragma once
// Triangle meshes of collision geometry (URDF <mesh filename=... scale=...>, task obstacles), read
// once when the robot or the task is read: STL, OBJ, Collada (DAE) and the other formats assimp
// reads. The triangles are in the mesh's own frame, already scaled.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into vertices
};

/// Reads `file` (sub-meshes with their node transforms), every vertex multiplied by `scale`
/// component-wise. InputError naming the file: unreadable, no triangles, or a vertex that is not a
/// finite number (the field names the vertex).
TriangleMesh readMeshFile(const std::filesystem::path& file, const Eigen::Vector3d& scale);

/// A MeshShape for `file` at `scale` with its triangles read (readMeshFile).
MeshShape loadMeshShape(const std::filesystem::path& file, const Eigen::Vector3d& scale);

}  // namespace pmdplan
