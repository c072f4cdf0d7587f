#pragma once
// Internal: the exact checker tests a mesh's triangles, so geometry wholly inside a closed mesh
// touches none of them. The exact checker adds this test for such pairs, so that a
// closed mesh is a solid as the primitives are: a point is inside where rays from it cross the
// surface an odd number of times (whatever way the triangles face). An open mesh has an inside
// only where its triangles happen to close around the point.
#include <Eigen/Geometry>
#include <memory>

#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {

class MeshInterior {
 public:
  explicit MeshInterior(std::shared_ptr<const TriangleMesh> mesh);
  /// Is `point` (in the mesh frame) inside the mesh?
  bool contains(const Eigen::Vector3d& point) const;

 private:
  std::shared_ptr<const TriangleMesh> mesh_;
  Eigen::AlignedBox3d box_;
};

}  // namespace pmdplan
