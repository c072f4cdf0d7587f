#pragma once
// Internal: the exact checker's route for a mesh against a primitive (primitive_contact.hpp has
// why FCL is not asked: its GJK calls a fingertip's tessellated sphere 0.02 mm inside a can
// free). The mesh is its triangles, each a convex part tested against the primitive with proven
// bounds after a bounding-sphere test; a closed mesh is a solid, so a primitive wholly inside it
// (its centre inside, mesh_containment.hpp) or a mesh wholly inside the primitive touches it too.
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "mesh_containment.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan {

struct MeshParts {
  std::vector<ConvexPart> triangles;  ///< in the mesh's frame
  double radius = 0.0;                ///< encloses every vertex around the mesh's origin
  std::shared_ptr<const MeshInterior> interior;
  Eigen::Vector3d vertex = Eigen::Vector3d::Zero();  ///< one vertex of the mesh (its frame)
};

MeshParts meshParts(std::shared_ptr<const TriangleMesh> mesh);

/// Does the mesh at `meshPose` touch `part` (in the world)? Touching unless proven apart.
bool meshTouchesPart(const MeshParts& mesh, const Eigen::Isometry3d& meshPose, const ConvexPart& part);

/// Their distance when apart (a lower bound to 1e-6 relative), 0 when they touch.
double meshPartDistance(const MeshParts& mesh, const Eigen::Isometry3d& meshPose, const ConvexPart& part);

}  // namespace pmdplan
