#include "pmdplan/collision/sphere_environment.hpp"

#include "fcl_geometry.hpp"

namespace pmdplan {
namespace {

SolidPrimitive placed(SolidPrimitive::Kind kind, const Eigen::Isometry3d& pose, double a, double b, double c) {
  SolidPrimitive p;
  p.kind = kind;
  for (int r = 0; r < 3; ++r) {
    p.centre[r] = pose.translation()(r);
    for (int k = 0; k < 3; ++k) p.rotation[r * 3 + k] = pose.linear()(r, k);
  }
  p.size[0] = a, p.size[1] = b, p.size[2] = c;
  return p;
}

SolidPrimitive primitiveOf(const Obstacle& obstacle) {
  using Kind = SolidPrimitive::Kind;
  if (const auto* box = std::get_if<BoxShape>(&obstacle.shape))
    return placed(Kind::Box, obstacle.pose, 0.5 * box->size.x(), 0.5 * box->size.y(), 0.5 * box->size.z());
  if (const auto* cylinder = std::get_if<CylinderShape>(&obstacle.shape))
    return placed(Kind::Cylinder, obstacle.pose, cylinder->radius, 0.5 * cylinder->length, 0.0);
  if (const auto* sphere = std::get_if<SphereShape>(&obstacle.shape)) return placed(Kind::Sphere, obstacle.pose, sphere->radius, 0.0, 0.0);
  // A mesh: its triangles' bounding box in the mesh frame (what FCL reads), a solid box around them.
  const auto geometry = makeFclGeometry(obstacle.shape);
  const auto& box = geometry->aabb_local;
  Eigen::Isometry3d pose = obstacle.pose;
  pose.translation() = obstacle.pose * (0.5 * (box.min_ + box.max_));
  const Eigen::Vector3d half = 0.5 * (box.max_ - box.min_);
  return placed(Kind::Box, pose, half.x(), half.y(), half.z());
}

}  // namespace

SphereEnvironment::SphereEnvironment(const std::vector<Obstacle>& obstacles) {
  for (const auto& obstacle : obstacles) {
    primitives_.push_back(primitiveOf(obstacle));
    SolidPrimitive box = primitives_.back();
    if (box.kind == SolidPrimitive::Kind::Cylinder)
      box.size[2] = box.size[1], box.size[1] = box.size[0];  // radius, radius, half length
    else if (box.kind == SolidPrimitive::Kind::Sphere)
      box.size[1] = box.size[2] = box.size[0];
    box.kind = SolidPrimitive::Kind::Box;
    boxes_.push_back(box);
  }
}

}  // namespace pmdplan
