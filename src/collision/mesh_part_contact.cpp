#include "mesh_part_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmdplan/collision/fast/convex_distance.hpp"
#include "primitive_contact.hpp"

namespace pmdplan {
namespace {

/// `part` moved from the world into the mesh's frame.
ConvexPart inMeshFrame(const Eigen::Isometry3d& meshPose, const ConvexPart& part) {
  const Eigen::Isometry3d inverse = meshPose.inverse();
  double pose[12];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose[r * 3 + c] = inverse.linear()(r, c);
    pose[9 + r] = inverse.translation()(r);
  }
  ConvexPart local;
  placePart(part, pose, local);
  return local;
}

double boundGap(const ConvexPart& a, const ConvexPart& b) {
  const double dx = a.boundCentre[0] - b.boundCentre[0], dy = a.boundCentre[1] - b.boundCentre[1],
               dz = a.boundCentre[2] - b.boundCentre[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - a.boundRadius - b.boundRadius;
}

}  // namespace

MeshParts meshParts(std::shared_ptr<const TriangleMesh> mesh) {
  MeshParts parts;
  for (const auto& t : mesh->triangles) {
    const Eigen::Vector3d &a = mesh->vertices[t[0]], &b = mesh->vertices[t[1]], &c = mesh->vertices[t[2]];
    parts.triangles.push_back(trianglePart(a.data(), b.data(), c.data()));
  }
  for (const auto& v : mesh->vertices) parts.radius = std::max(parts.radius, v.norm());
  parts.vertex = mesh->vertices[mesh->triangles.front()[0]];
  parts.interior = std::make_shared<const MeshInterior>(std::move(mesh));
  return parts;
}

bool meshTouchesPart(const MeshParts& mesh, const Eigen::Isometry3d& meshPose, const ConvexPart& part) {
  const ConvexPart local = inMeshFrame(meshPose, part);
  const double* c = local.boundCentre;
  if (std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > mesh.radius + local.boundRadius) return false;
  for (const auto& triangle : mesh.triangles)
    if (boundGap(triangle, local) <= 0.0 && primitivesTouch(triangle, local)) return true;
  // No triangle touches: one inside the other? (A point of the part, `a`, lies in it.)
  return mesh.interior->contains(Eigen::Vector3d(local.a[0], local.a[1], local.a[2])) ||
         primitiveContainsPoint(local, mesh.vertex.data());
}

double meshPartDistance(const MeshParts& mesh, const Eigen::Isometry3d& meshPose, const ConvexPart& part) {
  if (meshTouchesPart(mesh, meshPose, part)) return 0.0;
  const ConvexPart local = inMeshFrame(meshPose, part);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& triangle : mesh.triangles)
    if (boundGap(triangle, local) < best) best = std::min(best, primitiveSignedDistance(triangle, local));
  return best;
}

}  // namespace pmdplan
