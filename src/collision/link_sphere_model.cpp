#include "pmdplan/collision/link_sphere_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pmdplan {
namespace {

Sphere placedSphere(const Eigen::Isometry3d& pose, const Eigen::Vector3d& local, double radius) {
  const Eigen::Vector3d c = pose * local;
  return Sphere{{c.x(), c.y(), c.z()}, radius};
}

// A long cylinder (length >= its radius) of radius r and length L along local z is cut into k
// slices of height L/k; slice i is covered by a sphere on the axis at its middle z_i with radius
// R = sqrt(r^2 + (L/2k)^2). Proof: a point (rho, z) of the cylinder has rho <= r and lies in some
// slice, |z - z_i| <= L/2k, so its squared distance to that centre is rho^2 + (z - z_i)^2 <= R^2.
// The sphere pokes out radially by R - r, which picks k. Beyond a cap it stays inside the sphere of
// radius r on the cap centre (rho^2 <= R^2 - (dz + h)^2 <= r^2 - dz^2 for dz >= 0), so a capsule
// (cylinder with end spheres, as in the SAH/TX90 URDF) gains nothing there.
std::vector<Sphere> coverLongCylinder(const CylinderShape& c, const Eigen::Isometry3d& pose, const SphereCoverParameters& p) {
  const double r = c.radius;
  const double halfSliceLimit = std::sqrt((r + p.maxOvershoot) * (r + p.maxOvershoot) - r * r);
  int k = std::max(1, static_cast<int>(std::ceil(c.length / (2.0 * halfSliceLimit))));
  k = std::min(k, std::max(1, p.maxSpheresPerShape));
  const double h = c.length / (2.0 * k);
  const double radius = std::sqrt(r * r + h * h) + p.safetyMargin;
  std::vector<Sphere> spheres;
  for (int i = 0; i < k; ++i)
    spheres.push_back(placedSphere(pose, Eigen::Vector3d(0, 0, -0.5 * c.length + (2 * i + 1) * h), radius));
  return spheres;
}

// Box cut into an n_x x n_y x n_z grid of cells d = size / n; each cell is covered by the sphere
// on its centre with radius |d| / 2. Proof: every point of the box lies in some (closed) cell and
// differs from its centre by at most d_i / 2 along each axis, so by at most |d| / 2 in all.
// The sphere pokes out of a face by |d|/2 - min(d)/2: cells are refined until that
// is within the overshoot (or the sphere count limit is reached): the cell is split along its
// longest side, one more cell at a time.
std::vector<Eigen::Vector3d> gridCells(const Eigen::Vector3d& size, const SphereCoverParameters& p, Eigen::Vector3d& cellSize) {
  int n[3] = {1, 1, 1};
  const auto cell = [&](int axis) { return size[axis] / n[axis]; };
  const auto overshoot = [&] {
    const double d[3] = {cell(0), cell(1), cell(2)};
    return 0.5 * (std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - std::min({d[0], d[1], d[2]}));
  };
  while (overshoot() > p.maxOvershoot) {
    int longest = 0;
    for (int axis = 1; axis < 3; ++axis)
      if (cell(axis) > cell(longest)) longest = axis;
    const int grown = n[longest] + 1;
    if ((n[0] * n[1] * n[2] / n[longest]) * grown > p.maxSpheresPerShape) break;
    n[longest] = grown;
  }
  cellSize = Eigen::Vector3d(cell(0), cell(1), cell(2));
  std::vector<Eigen::Vector3d> centres;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k)
        centres.push_back(-0.5 * size + Eigen::Vector3d((i + 0.5) * cellSize.x(), (j + 0.5) * cellSize.y(), (k + 0.5) * cellSize.z()));
  return centres;
}

std::vector<Sphere> coverBox(const BoxShape& b, const Eigen::Isometry3d& pose, const SphereCoverParameters& p) {
  Eigen::Vector3d d;
  const auto centres = gridCells(b.size, p, d);
  std::vector<Sphere> spheres;
  for (const auto& centre : centres) spheres.push_back(placedSphere(pose, centre, 0.5 * d.norm() + p.safetyMargin));
  return spheres;
}

// A flat cylinder (a disk, length < radius) would get huge slice spheres poking far beyond its
// caps, so it is covered like its bounding box [-r, r]^2 x [-L/2, L/2] (proof as for boxes), keeping
// only the cells that meet the cylinder (cell nearest point within r of the axis): every point of
// the cylinder lies in a kept cell.
std::vector<Sphere> coverFlatCylinder(const CylinderShape& c, const Eigen::Isometry3d& pose, const SphereCoverParameters& p) {
  Eigen::Vector3d d;
  const auto centres = gridCells(Eigen::Vector3d(2 * c.radius, 2 * c.radius, c.length), p, d);
  std::vector<Sphere> spheres;
  for (const auto& centre : centres) {
    const double nx = std::max(std::abs(centre.x()) - 0.5 * d.x(), 0.0), ny = std::max(std::abs(centre.y()) - 0.5 * d.y(), 0.0);
    if (nx * nx + ny * ny > c.radius * c.radius) continue;
    spheres.push_back(placedSphere(pose, centre, 0.5 * d.norm() + p.safetyMargin));
  }
  return spheres;
}

}  // namespace

std::vector<Sphere> coverShape(const Shape& shape, const Eigen::Isometry3d& pose, const SphereCoverParameters& p) {
  if (!(p.maxOvershoot > 0.0) || !(p.safetyMargin >= 0.0) || p.maxSpheresPerShape < 1)
    throw std::invalid_argument("sphere cover: the overshoot must be positive, the margin >= 0, the sphere limit >= 1");
  if (const auto* box = std::get_if<BoxShape>(&shape)) return coverBox(*box, pose, p);
  if (const auto* cylinder = std::get_if<CylinderShape>(&shape))
    return cylinder->length >= cylinder->radius ? coverLongCylinder(*cylinder, pose, p) : coverFlatCylinder(*cylinder, pose, p);
  if (const auto* sphere = std::get_if<SphereShape>(&shape))
    return {placedSphere(pose, Eigen::Vector3d::Zero(), sphere->radius + p.safetyMargin)};
  throw std::invalid_argument("sphere cover: robot links with meshes are not supported by the fast checker");
}

Sphere enclosingSphere(const std::vector<Sphere>& spheres) {
  if (spheres.empty()) return {};
  double low[3], high[3];
  for (int a = 0; a < 3; ++a) {
    low[a] = spheres.front().centre[a] - spheres.front().radius;
    high[a] = spheres.front().centre[a] + spheres.front().radius;
  }
  for (const auto& s : spheres)
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], s.centre[a] - s.radius);
      high[a] = std::max(high[a], s.centre[a] + s.radius);
    }
  Sphere bound;
  for (int a = 0; a < 3; ++a) bound.centre[a] = 0.5 * (low[a] + high[a]);
  for (const auto& s : spheres) {
    const double dx = s.centre[0] - bound.centre[0], dy = s.centre[1] - bound.centre[1], dz = s.centre[2] - bound.centre[2];
    bound.radius = std::max(bound.radius, std::sqrt(dx * dx + dy * dy + dz * dz) + s.radius);
  }
  // Rounding of the sum above must not leave a sphere poking out by an ulp.
  bound.radius *= 1.0 + 1e-12;
  return bound;
}

namespace {

struct GroupBuild {
  GroupKind kind = GroupKind::Spheres;
  std::vector<Sphere> cover;
  Sphere bound;
  SolidPrimitive box;
  Capsule capsule;
};

double pointSegmentDistance(const double* point, const Capsule& capsule) {
  return segmentDistance(point, point, capsule.a, capsule.b);
}

/// The groups of one link: cylinders as capsules (long ones) or sphere groups (disks), spheres
/// merged into a capsule that contains them (else their own point capsule), boxes as boxes.
std::vector<GroupBuild> linkGroups(const std::vector<PlacedShape>& shapes, const SphereCoverParameters& p) {
  std::vector<GroupBuild> groups;
  const auto vec = [](const Eigen::Vector3d& v, double* out) { out[0] = v.x(), out[1] = v.y(), out[2] = v.z(); };
  for (const auto& placed : shapes) {
    const auto* cylinder = std::get_if<CylinderShape>(&placed.shape);
    if (!cylinder) continue;
    GroupBuild g;
    g.cover = coverShape(placed.shape, placed.pose, p);
    g.bound = placedSphere(placed.pose, Eigen::Vector3d::Zero(), boundingRadius(placed.shape) + p.safetyMargin);
    if (cylinder->length >= cylinder->radius) {
      // Every point of the cylinder is within its radius of its axis segment.
      g.kind = GroupKind::Capsule;
      vec(placed.pose * Eigen::Vector3d(0, 0, -0.5 * cylinder->length), g.capsule.a);
      vec(placed.pose * Eigen::Vector3d(0, 0, 0.5 * cylinder->length), g.capsule.b);
      g.capsule.radius = cylinder->radius + p.safetyMargin;
      g.bound.radius = 0.5 * cylinder->length + g.capsule.radius;  // encloses the capsule too
    }
    groups.push_back(std::move(g));
  }
  for (const auto& placed : shapes) {
    const auto* sphere = std::get_if<SphereShape>(&placed.shape);
    if (!sphere) continue;
    const Sphere s = coverShape(placed.shape, placed.pose, p).front();
    bool merged = false;
    for (auto& g : groups)
      if (const double reach = pointSegmentDistance(s.centre, g.capsule) + s.radius;
          g.kind == GroupKind::Capsule && reach <= g.capsule.radius + 1e-12) {
        // The capsule contains the sphere (end caps of the SAH phalanges); a rounding excess of
        // the test is added to the capsule and its bound so the containment stays exact.
        g.capsule.radius = std::max(g.capsule.radius, reach);
        g.bound.radius += 1e-12;
        g.cover.push_back(s);
        merged = true;
        break;
      }
    if (merged) continue;
    GroupBuild g;
    g.kind = GroupKind::Capsule;
    g.cover = {s};
    g.bound = s;
    for (int i = 0; i < 3; ++i) g.capsule.a[i] = g.capsule.b[i] = s.centre[i];
    g.capsule.radius = s.radius;
    groups.push_back(std::move(g));
  }
  for (const auto& placed : shapes) {
    const auto* box = std::get_if<BoxShape>(&placed.shape);
    if (!box) continue;
    GroupBuild g;
    g.kind = GroupKind::Box;
    g.cover = coverShape(placed.shape, placed.pose, p);
    g.bound = placedSphere(placed.pose, Eigen::Vector3d::Zero(), boundingRadius(placed.shape) + p.safetyMargin);
    for (int r = 0; r < 3; ++r) {
      g.box.centre[r] = placed.pose.translation()(r);
      for (int k = 0; k < 3; ++k) g.box.rotation[r * 3 + k] = placed.pose.linear()(r, k);
      g.box.size[r] = 0.5 * box->size[r] + p.safetyMargin;
    }
    groups.push_back(std::move(g));
  }
  for (const auto& placed : shapes)
    if (std::holds_alternative<MeshShape>(placed.shape)) coverShape(placed.shape, placed.pose, p);  // throws: unsupported
  return groups;
}

}  // namespace

LinkSphereModel::LinkSphereModel(const RobotModel& model, const SphereCoverParameters& parameters)
    : parameters_(parameters), links_(model.links().size()) {
  for (std::size_t l = 0; l < model.links().size(); ++l) {
    auto& link = links_[l];
    for (const auto& g : linkGroups(model.links()[l].collisionShapes, parameters)) {
      for (const auto& s : g.cover) {
        link.x.push_back(s.centre[0]);
        link.y.push_back(s.centre[1]);
        link.z.push_back(s.centre[2]);
        link.radius.push_back(s.radius);
      }
      link.groupBegin.push_back(link.sphereCount());
      link.groupBounds.push_back(g.bound);
      link.groupKind.push_back(g.kind);
      link.groupBoxes.push_back(g.box);
      link.groupCapsules.push_back(g.capsule);
    }
    link.bound = enclosingSphere(link.groupBounds);
  }
}

int LinkSphereModel::sphereCount() const {
  int total = 0;
  for (const auto& link : links_) total += link.sphereCount();
  return total;
}

}  // namespace pmdplan
