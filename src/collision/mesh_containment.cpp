#include "mesh_containment.hpp"

#include <utility>

namespace pmdplan {
namespace {

/// Does the ray from `origin` along `direction` cross the triangle (Moller and Trumbore)?
bool crosses(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& a,
             const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, p = direction.cross(ac);
  const double determinant = ab.dot(p);
  if (determinant == 0.0) return false;
  const double inverse = 1.0 / determinant;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) * inverse;
  if (u < 0.0 || u > 1.0) return false;
  const Eigen::Vector3d q = s.cross(ab);
  const double v = direction.dot(q) * inverse;
  if (v < 0.0 || u + v > 1.0) return false;
  return ac.dot(q) * inverse > 0.0;
}

}  // namespace

MeshInterior::MeshInterior(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)) {
  for (const auto& v : mesh_->vertices) box_.extend(v);
}

bool MeshInterior::contains(const Eigen::Vector3d& point) const {
  if (!box_.contains(point)) return false;
  // Three rays in unrelated directions, each inside if it crosses the surface an odd number of
  // times; the majority decides (a ray through an edge or a vertex may count wrong).
  static const Eigen::Vector3d directions[3] = {Eigen::Vector3d(0.5773, 0.6213, 0.5301).normalized(),
                                                Eigen::Vector3d(-0.4187, 0.8124, -0.4059).normalized(),
                                                Eigen::Vector3d(0.7071, -0.3122, -0.6346).normalized()};
  const auto& v = mesh_->vertices;
  int inside = 0;
  for (const auto& direction : directions) {
    bool odd = false;
    for (const auto& t : mesh_->triangles) odd ^= crosses(point, direction, v[t[0]], v[t[1]], v[t[2]]);
    inside += odd;
  }
  return inside >= 2;
}

}  // namespace pmdplan
