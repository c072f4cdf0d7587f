#include "pmdplan/collision/link_part_model.hpp"

#include <algorithm>
#include <cmath>

#include "mesh_enclosure.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"
#include "urdf_capsules.hpp"

namespace pmdplan {
namespace {

void plainPose(const Eigen::Isometry3d& pose, double* out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 3 + c] = pose.linear()(r, c);
    out[9 + r] = pose.translation()(r);
  }
}

void plainPoint(const Eigen::Vector3d& p, double* out) { out[0] = p.x(), out[1] = p.y(), out[2] = p.z(); }

LinkParts partsOf(const RobotModel& model, std::size_t link) {
  const auto& shapes = model.links()[link].collisionShapes;
  std::vector<char> used(shapes.size(), 0);
  LinkParts result;
  // Cylinders first: with a sphere of their radius on both cap centres they are capsules.
  for (const UrdfCapsule& capsule : urdfCapsules(shapes)) {
    const PlacedShape& placed = shapes[static_cast<std::size_t>(capsule.cylinder)];
    const auto& cylinder = std::get<CylinderShape>(placed.shape);
    used[static_cast<std::size_t>(capsule.cylinder)] = 1;
    if (capsule.capA >= 0) {
      used[static_cast<std::size_t>(capsule.capA)] = used[static_cast<std::size_t>(capsule.capB)] = 1;
      double pa[3], pb[3];
      plainPoint(placed.pose * Eigen::Vector3d(0, 0, -0.5 * cylinder.length), pa);
      plainPoint(placed.pose * Eigen::Vector3d(0, 0, 0.5 * cylinder.length), pb);
      result.parts.push_back(capsulePart(pa, pb, capsule.radius));
    } else {
      double pose[12];
      plainPose(placed.pose, pose);
      result.parts.push_back(cylinderPart(pose, cylinder.radius, 0.5 * cylinder.length));
    }
  }
  // Spheres: dropped when a capsule already contains them, else point capsules.
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const auto* sphere = std::get_if<SphereShape>(&shapes[i].shape);
    if (!sphere || used[i]) continue;
    double c[3];
    plainPoint(shapes[i].pose.translation(), c);
    const bool inside = std::any_of(result.parts.begin(), result.parts.end(), [&](const ConvexPart& p) {
      return p.kind == ConvexPart::Kind::Capsule && segmentDistance(c, c, p.a, p.b) + sphere->radius <= p.radius;
    });
    if (!inside) result.parts.push_back(capsulePart(c, c, sphere->radius));
  }
  for (const auto& placed : shapes) {
    if (const auto* box = std::get_if<BoxShape>(&placed.shape)) {
      double pose[12];
      plainPose(placed.pose, pose);
      const double half[3] = {0.5 * box->size.x(), 0.5 * box->size.y(), 0.5 * box->size.z()};
      result.parts.push_back(boxPart(pose, half));
    } else if (const auto* mesh = std::get_if<MeshShape>(&placed.shape)) {
      result.parts.push_back(meshEnclosure(*mesh, placed.pose));
    }
  }
  if (result.parts.empty()) return result;
  // The bound: centred in the box around the parts' bounds, reaching the farthest of them.
  double low[3], high[3];
  for (int k = 0; k < 3; ++k) low[k] = INFINITY, high[k] = -INFINITY;
  for (const auto& p : result.parts)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p.boundCentre[k] - p.boundRadius);
      high[k] = std::max(high[k], p.boundCentre[k] + p.boundRadius);
    }
  for (int k = 0; k < 3; ++k) result.boundCentre[k] = 0.5 * (low[k] + high[k]);
  for (const auto& p : result.parts) {
    const double dx = p.boundCentre[0] - result.boundCentre[0], dy = p.boundCentre[1] - result.boundCentre[1],
                 dz = p.boundCentre[2] - result.boundCentre[2];
    result.boundRadius = std::max(result.boundRadius, std::sqrt(dx * dx + dy * dy + dz * dz) + p.boundRadius);
  }
  result.boundRadius *= 1.0 + 1e-12;  // rounding of the sum must not leave a part poking out
  return result;
}

}  // namespace

std::vector<LinkParts> linkParts(const RobotModel& model) {
  std::vector<LinkParts> links;
  for (std::size_t l = 0; l < model.links().size(); ++l) links.push_back(partsOf(model, l));
  return links;
}

std::vector<ObstaclePart> obstacleParts(const std::vector<Obstacle>& obstacles) {
  std::vector<ObstaclePart> parts;
  for (const auto& obstacle : obstacles) {
    double pose[12];
    plainPose(obstacle.pose, pose);
    if (const auto* box = std::get_if<BoxShape>(&obstacle.shape)) {
      const double half[3] = {0.5 * box->size.x(), 0.5 * box->size.y(), 0.5 * box->size.z()};
      parts.push_back({boxPart(pose, half), true});
    } else if (const auto* cylinder = std::get_if<CylinderShape>(&obstacle.shape)) {
      parts.push_back({cylinderPart(pose, cylinder->radius, 0.5 * cylinder->length), true});
    } else if (const auto* sphere = std::get_if<SphereShape>(&obstacle.shape)) {
      parts.push_back({capsulePart(pose + 9, pose + 9, sphere->radius), true});
    } else {
      // A mesh: its enclosure, which only ever proves "apart".
      parts.push_back({meshEnclosure(std::get<MeshShape>(obstacle.shape), obstacle.pose), false});
    }
  }
  return parts;
}

}  // namespace pmdplan
