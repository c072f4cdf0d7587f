#pragma once
// Triangle meshes of collision geometry (URDF <mesh filename=... scale=...>, task obstacles), read
// once when the robot or the task is read: STL, OBJ and COLLADA (.dae), through assimp. The
// triangles are in the mesh's own frame, already scaled.
//
// A mesh file is hostile input like any other (docs/robustness.md): before assimp sees it, it must
// be a regular file (checked with stat, so a FIFO never blocks) of at most kMaxMeshFileBytes with
// one of the three extensions, and a cheap scan bounds what assimp would build from it (an OBJ's
// faces, a binary STL's triangle count, a COLLADA file's node graph: no instance_node cycle — assimp
// recursed on one until the stack overflowed — bounded nesting and instances). assimp reads the
// bytes from memory and may open no other file (an OBJ's material library is skipped). After the
// import the triangles per mesh are bounded, and MeshTriangleBudget bounds them per robot or task.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan {

/// The bounds of a mesh file, measured with `pmdplan check` on a task whose robot or obstacle holds
/// such a mesh (docs/robustness.md): 100,000 triangles take about 1 s and 140 MB, 200,000 about
/// 2.3 s and 260 MB (a 10^6-triangle STL took 49 s and 906 MB).
struct MeshLimits {
  /// The largest mesh file (16 MiB): a binary STL of 335,000 triangles, an ASCII STL of ~200,000;
  /// assimp reads any such file in under 0.5 s (the scans below refuse the denser OBJ and COLLADA
  /// files that would make it build millions of faces first).
  static constexpr std::size_t kMaxFileBytes = std::size_t{16} << 20;
  /// Triangles of one mesh file, after triangulation and with every node instance counted.
  static constexpr std::size_t kMaxTriangles = 100'000;
  /// Triangles of all the collision meshes of one robot, and of all the obstacle meshes of a task.
  static constexpr std::size_t kMaxTrianglesTogether = 200'000;
  /// Corners of one polygon before triangulation (assimp's ear clipping is quadratic in them).
  static constexpr std::size_t kMaxPolygonCorners = 256;
  /// COLLADA: nodes nested in nodes, through children and <instance_node> alike.
  static constexpr std::size_t kMaxColladaNodeDepth = 32;
  /// COLLADA: nodes once every <instance_node> is expanded (each instances its target's subtree).
  static constexpr std::size_t kMaxColladaNodeInstances = 10'000;
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< indices into vertices
};

/// Reads `file` (sub-meshes with their node transforms), every vertex multiplied by `scale`
/// component-wise. InputError naming the file: not a regular .stl, .obj or .dae file, beyond
/// MeshLimits, unreadable, no triangles, a scale outside ShapeBounds, or a scaled vertex that is
/// not finite or lies more than ShapeBounds::kMaxLength from the mesh's frame (the field names the
/// vertex).
TriangleMesh readMeshFile(const std::filesystem::path& file, const Eigen::Vector3d& scale);

/// A MeshShape for `file` at `scale` with its triangles read (readMeshFile).
MeshShape loadMeshShape(const std::filesystem::path& file, const Eigen::Vector3d& scale);

/// The file extensions readMeshFile reads (lower case, with the dot), and whether `file` has one
/// (in any case).
const std::vector<std::string>& meshFileExtensions();
bool hasMeshFileExtension(const std::filesystem::path& file);

/// Counts the triangles of the meshes of one robot or one task against
/// MeshLimits::kMaxTrianglesTogether; `what` names them in the message ("collision meshes of the robot").
class MeshTriangleBudget {
 public:
  explicit MeshTriangleBudget(std::string what) : what_(std::move(what)) {}
  /// Adds a read mesh; InputError(file, field) once the total passes the bound.
  void add(const MeshShape& mesh, const std::string& file, const std::string& field);

 private:
  std::string what_;
  std::size_t total_ = 0;
};

}  // namespace pmdplan
