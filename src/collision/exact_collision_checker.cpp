#include "pmdplan/collision/exact_collision_checker.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "fcl_geometry.hpp"
#include "mesh_part_contact.hpp"
#include "pmdplan/collision/link_part_model.hpp"
#include "primitive_contact.hpp"

namespace pmdplan {

struct PlacedGeometry {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  Eigen::Isometry3d pose;  ///< in the link frame (robot) or the world (obstacles)
  double radius = 0.0;     ///< encloses the geometry around pose.translation()
  /// Meshes: their triangles as convex parts and their inside (mesh_part_contact.hpp). Primitives
  /// are convex parts too (Geometry::parts, obstacleParts).
  std::shared_ptr<const MeshParts> mesh;
};

/// An obstacle with its world-aligned bounding box: large flat obstacles (floor, table) have huge
/// bounding spheres, so robot spheres are tested against the box instead.
struct PlacedObstacle : PlacedGeometry {
  Eigen::Vector3d boxMin, boxMax;
};

/// A link's bounding sphere, centred among its shapes (in the link frame).
struct LinkSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

struct ExactCollisionChecker::Geometry {
  std::vector<std::vector<PlacedGeometry>> links;    ///< per link, every shape for FCL (used where a mesh is involved)
  std::vector<LinkParts> parts;                      ///< per link, its primitives as convex parts (meshes skipped)
  std::vector<ObstaclePart> obstacleParts;           ///< per obstacle, in the world (exact = false: a mesh)
  mutable std::vector<ConvexPart> placedA, placedB;  ///< scratch: parts posed in the world
  std::vector<LinkSphere> linkSpheres;
  std::vector<std::pair<int, int>> selfPairs;  ///< enabled link pairs that both have geometry
  std::vector<PlacedObstacle> obstacles;
  fcl::CollisionRequestd request;
  fcl::DistanceRequestd distanceRequest;
};

namespace {

bool spheresApart(const Eigen::Vector3d& a, double ra, const Eigen::Vector3d& b, double rb) {
  return (a - b).squaredNorm() > (ra + rb) * (ra + rb);
}

bool sphereOutsideBox(const Eigen::Vector3d& centre, double radius, const PlacedObstacle& box) {
  const Eigen::Vector3d nearest = centre.cwiseMax(box.boxMin).cwiseMin(box.boxMax);
  return (centre - nearest).squaredNorm() > radius * radius;
}

/// FCL, for two meshes (triangle against triangle); a primitive takes primitive_contact.hpp's or
/// mesh_part_contact.hpp's route.
bool meshesCollide(const PlacedGeometry& a, const Eigen::Isometry3d& poseA, const PlacedGeometry& b,
                   const Eigen::Isometry3d& poseB, const fcl::CollisionRequestd& request) {
  if (!a.mesh || !b.mesh) return false;
  if (spheresApart(poseA.translation(), a.radius, poseB.translation(), b.radius)) return false;
  fcl::CollisionResultd result;
  fcl::collide(a.geometry.get(), poseA, b.geometry.get(), poseB, request, result);
  if (result.isCollision()) return true;
  // No triangle touched: one wholly inside the other (mesh_containment.hpp)?
  return b.mesh->interior->contains(poseB.inverse() * (poseA * a.mesh->vertex)) ||
         a.mesh->interior->contains(poseA.inverse() * (poseB * b.mesh->vertex));
}

/// Geometry for `shape` placed at `pose`; for a mesh, its triangles and inside too.
PlacedGeometry placedGeometry(const Shape& shape, const Eigen::Isometry3d& pose) {
  PlacedGeometry placed;
  placed.geometry = makeFclGeometry(shape);
  placed.pose = pose;
  placed.radius = enclosingRadius(shape, *placed.geometry);
  if (const auto* mesh = std::get_if<MeshShape>(&shape))
    placed.mesh = std::make_shared<const MeshParts>(
        meshParts(mesh->triangles ? mesh->triangles
                                  : std::make_shared<const TriangleMesh>(readMeshFile(mesh->file, mesh->scale))));
  return placed;
}

/// FCL's distance between two meshes, or minus their penetration depth when they
/// overlap. Whether they overlap is the collision test's answer; the depth is FCL's signed
/// distance, which only its libccd solver computes (EPA); a depth it misses counts as touching (0).
double signedDistance(const PlacedGeometry& a, const Eigen::Isometry3d& poseA, const PlacedGeometry& b,
                      const Eigen::Isometry3d& poseB, const fcl::CollisionRequestd& collisionRequest,
                      const fcl::DistanceRequestd& distanceRequest) {
  fcl::CollisionResultd contact;
  fcl::collide(a.geometry.get(), poseA, b.geometry.get(), poseB, collisionRequest, contact);
  fcl::DistanceRequestd request = distanceRequest;
  if (contact.isCollision()) {
    request.enable_signed_distance = true;
    request.gjk_solver_type = fcl::GST_LIBCCD;
  }
  fcl::DistanceResultd result;
  fcl::distance(a.geometry.get(), poseA, b.geometry.get(), poseB, request, result);
  return contact.isCollision() ? std::min(result.min_distance, 0.0) : std::max(result.min_distance, 0.0);
}

}  // namespace

ExactCollisionChecker::ExactCollisionChecker(const Task& task)
    : task_(task), model_(*task.robot), kinematics_(*task.robot, task.base), geometry_(std::make_unique<Geometry>()) {
  auto& g = *geometry_;
  g.request.gjk_solver_type = fcl::GST_INDEP;
  g.request.num_max_contacts = 1;
  g.distanceRequest.gjk_solver_type = fcl::GST_INDEP;
  g.distanceRequest.enable_nearest_points = false;

  const auto& links = model_.links();
  g.links.resize(links.size());
  g.linkSpheres.resize(links.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    const auto& shapes = links[l].collisionShapes;
    for (const auto& placed : shapes) g.links[l].push_back(placedGeometry(placed.shape, placed.pose));
    if (g.links[l].empty()) continue;
    // Centre: the middle of the shapes' bounding-sphere box; radius: what reaches every shape.
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = -low;
    for (const auto& shape : g.links[l]) {
      low = low.cwiseMin((shape.pose.translation().array() - shape.radius).matrix());
      high = high.cwiseMax((shape.pose.translation().array() + shape.radius).matrix());
    }
    auto& sphere = g.linkSpheres[l];
    sphere.centre = 0.5 * (low + high);
    for (const auto& shape : g.links[l])
      sphere.radius = std::max(sphere.radius, (shape.pose.translation() - sphere.centre).norm() + shape.radius);
  }
  for (std::size_t a = 0; a < links.size(); ++a)
    for (std::size_t b = a + 1; b < links.size(); ++b)
      if (!g.links[a].empty() && !g.links[b].empty() &&
          !model_.isCollisionPairDisabled(static_cast<int>(a), static_cast<int>(b)))
        g.selfPairs.emplace_back(static_cast<int>(a), static_cast<int>(b));
  // Two primitives go our own route (primitive_contact.hpp); FCL sees the pairs with a mesh.
  g.parts = linkParts(model_);
  for (auto& link : g.parts)
    link.parts.erase(
        std::remove_if(link.parts.begin(), link.parts.end(), [](const ConvexPart& p) { return p.enclosure; }),
        link.parts.end());
  g.obstacleParts = obstacleParts(task.obstacles);
  for (const auto& obstacle : task.obstacles) {
    PlacedObstacle placed;
    static_cast<PlacedGeometry&>(placed) = placedGeometry(obstacle.shape, obstacle.pose);
    const fcl::AABBd& box = placed.geometry->aabb_local;
    // World box of the rotated local box: its eight corners.
    placed.boxMin = Eigen::Vector3d::Constant(1e300);
    placed.boxMax = -placed.boxMin;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d local((corner & 1) ? box.max_.x() : box.min_.x(),
                                  (corner & 2) ? box.max_.y() : box.min_.y(),
                                  (corner & 4) ? box.max_.z() : box.min_.z());
      const Eigen::Vector3d world = obstacle.pose * local;
      placed.boxMin = placed.boxMin.cwiseMin(world);
      placed.boxMax = placed.boxMax.cwiseMax(world);
    }
    g.obstacles.push_back(std::move(placed));
  }

  // Links whose pose depends on arm joints only (the hand's palm included): Algorithm 1's arm check.
  std::vector<char> armJoint(model_.joints().size(), 0);
  if (model_.hasGroup("arm"))
    for (std::size_t j = 0; j < model_.joints().size(); ++j) {
      const auto& joint = model_.joints()[j];
      const auto& arm = model_.group("arm");
      armJoint[j] = joint.type == JointType::Fixed ||
                    (joint.activeIndex >= 0 && std::find(arm.begin(), arm.end(), joint.activeIndex) != arm.end());
    }
  armLink_.assign(links.size(), 0);
  armLink_[static_cast<std::size_t>(model_.rootLink())] = 1;
  for (int j : model_.jointOrder()) {
    const auto& joint = model_.joints()[static_cast<std::size_t>(j)];
    armLink_[static_cast<std::size_t>(joint.childLink)] =
        armLink_[static_cast<std::size_t>(joint.parentLink)] && armJoint[static_cast<std::size_t>(j)];
  }
}

ExactCollisionChecker::~ExactCollisionChecker() = default;

const std::vector<std::pair<int, int>>& ExactCollisionChecker::selfPairs() const { return geometry_->selfPairs; }

namespace {

void plainPose(const Eigen::Isometry3d& pose, double* out) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[r * 3 + c] = pose.linear()(r, c);
    out[9 + r] = pose.translation()(r);
  }
}

/// The link's primitive parts posed in the world, into `placed`.
const std::vector<ConvexPart>& placeParts(const LinkParts& link, const Eigen::Isometry3d& pose,
                                          std::vector<ConvexPart>& placed) {
  double plain[12];
  plainPose(pose, plain);
  placed.resize(link.parts.size());
  for (std::size_t p = 0; p < link.parts.size(); ++p) placePart(link.parts[p], plain, placed[p]);
  return placed;
}

bool boundsApart(const ConvexPart& a, const ConvexPart& b) {
  return spheresApart(Eigen::Vector3d(a.boundCentre[0], a.boundCentre[1], a.boundCentre[2]), a.boundRadius,
                      Eigen::Vector3d(b.boundCentre[0], b.boundCentre[1], b.boundCentre[2]), b.boundRadius);
}

bool anyTouch(const std::vector<ConvexPart>& as, const std::vector<ConvexPart>& bs) {
  for (const auto& a : as)
    for (const auto& b : bs)
      if (!boundsApart(a, b) && primitivesTouch(a, b)) return true;
  return false;
}

/// Any mesh of `shapes` (posed by `pose`) against any of `parts` (in the world).
bool meshTouchesAny(const std::vector<PlacedGeometry>& shapes, const Eigen::Isometry3d& pose,
                    const std::vector<ConvexPart>& parts) {
  for (const auto& shape : shapes)
    if (shape.mesh)
      for (const auto& part : parts)
        if (meshTouchesPart(*shape.mesh, pose * shape.pose, part)) return true;
  return false;
}

}  // namespace

bool ExactCollisionChecker::linkPairCollides(const LinkPoses& poses, int a, int b) const {
  const auto& g = *geometry_;
  const auto& pa = poses[static_cast<std::size_t>(a)];
  const auto& pb = poses[static_cast<std::size_t>(b)];
  const auto& sa = g.linkSpheres[static_cast<std::size_t>(a)];
  const auto& sb = g.linkSpheres[static_cast<std::size_t>(b)];
  if (spheresApart(pa * sa.centre, sa.radius, pb * sb.centre, sb.radius)) return false;
  const auto& shapesA = g.links[static_cast<std::size_t>(a)];
  const auto& shapesB = g.links[static_cast<std::size_t>(b)];
  const auto& partsA = placeParts(g.parts[static_cast<std::size_t>(a)], pa, g.placedA);
  const auto& partsB = placeParts(g.parts[static_cast<std::size_t>(b)], pb, g.placedB);
  if (anyTouch(partsA, partsB) || meshTouchesAny(shapesA, pa, partsB) || meshTouchesAny(shapesB, pb, partsA))
    return true;
  for (const auto& shapeA : shapesA)
    for (const auto& shapeB : shapesB)
      if (meshesCollide(shapeA, pa * shapeA.pose, shapeB, pb * shapeB.pose, g.request)) return true;
  return false;
}

bool ExactCollisionChecker::linkObstacleCollides(const LinkPoses& poses, int link, std::size_t o) const {
  const auto& g = *geometry_;
  const auto l = static_cast<std::size_t>(link);
  if (g.links[l].empty()) return false;
  const auto& pose = poses[l];
  const auto& obstacle = g.obstacles[o];
  if (sphereOutsideBox(pose * g.linkSpheres[l].centre, g.linkSpheres[l].radius, obstacle)) return false;
  const auto& parts = placeParts(g.parts[l], pose, g.placedA);
  if (!obstacle.mesh) {  // a primitive: against the link's parts, then its meshes
    g.placedB.assign(1, g.obstacleParts[o].part);
    return anyTouch(parts, g.placedB) || meshTouchesAny(g.links[l], pose, g.placedB);
  }
  for (const auto& part : parts)
    if (meshTouchesPart(*obstacle.mesh, obstacle.pose, part)) return true;
  return std::any_of(g.links[l].begin(), g.links[l].end(), [&](const PlacedGeometry& shape) {
    const Eigen::Isometry3d shapePose = pose * shape.pose;
    return !sphereOutsideBox(shapePose.translation(), shape.radius, obstacle) &&
           meshesCollide(shape, shapePose, obstacle, obstacle.pose, g.request);
  });
}

bool ExactCollisionChecker::selfCollides(const LinkPoses& poses, bool armOnly, CollisionReport* report) const {
  bool collides = false;
  for (auto [a, b] : geometry_->selfPairs) {
    if (armOnly && !(armLink_[static_cast<std::size_t>(a)] && armLink_[static_cast<std::size_t>(b)])) continue;
    if (!linkPairCollides(poses, a, b)) continue;
    collides = true;
    if (!report) return true;
    report->pairs.emplace_back(model_.links()[static_cast<std::size_t>(a)].name,
                               model_.links()[static_cast<std::size_t>(b)].name);
  }
  return collides;
}

bool ExactCollisionChecker::environmentCollides(const LinkPoses& poses, CollisionReport* report) const {
  const auto& g = *geometry_;
  bool collides = false;
  for (std::size_t l = 0; l < g.links.size(); ++l)
    for (std::size_t o = 0; o < g.obstacles.size(); ++o) {
      if (!linkObstacleCollides(poses, static_cast<int>(l), o)) continue;
      collides = true;
      if (!report) return true;
      report->pairs.emplace_back(model_.links()[l].name, task_.obstacles[o].name);
    }
  return collides;
}

bool ExactCollisionChecker::isValid(const Configuration& q) {
  ++checks_;
  kinematics_.linkPoses(q, poses_);
  return !selfCollides(poses_, false, nullptr) && !environmentCollides(poses_, nullptr);
}

bool ExactCollisionChecker::isArmValid(const Configuration& q) {
  ++checks_;
  kinematics_.linkPoses(q, poses_);
  return !selfCollides(poses_, true, nullptr);
}

CollisionReport ExactCollisionChecker::check(const Configuration& q) {
  ++checks_;
  kinematics_.linkPoses(q, poses_);
  CollisionReport report;
  selfCollides(poses_, false, &report);
  environmentCollides(poses_, &report);
  std::sort(report.pairs.begin(), report.pairs.end());
  return report;
}

double ExactCollisionChecker::linkObstacleDistance(int link, std::size_t o) const {
  const auto& g = *geometry_;
  const auto l = static_cast<std::size_t>(link);
  const auto& obstacle = g.obstacles[o];
  double best = std::numeric_limits<double>::infinity();
  for (const auto& part : placeParts(g.parts[l], poses_[l], g.placedA))
    best = std::min(best, obstacle.mesh ? meshPartDistance(*obstacle.mesh, obstacle.pose, part)
                                        : primitiveSignedDistance(part, g.obstacleParts[o].part));
  for (const auto& shape : g.links[l]) {
    if (!shape.mesh) continue;
    const Eigen::Isometry3d shapePose = poses_[l] * shape.pose;
    best = std::min(best, obstacle.mesh
                              ? signedDistance(shape, shapePose, obstacle, obstacle.pose, g.request, g.distanceRequest)
                              : meshPartDistance(*shape.mesh, shapePose, g.obstacleParts[o].part));
  }
  return best;
}

double ExactCollisionChecker::distanceToObstacle(const Configuration& q, const std::vector<int>& links,
                                                 const std::string& obstacleName) {
  const auto& g = *geometry_;
  std::size_t o = 0;
  while (o < task_.obstacles.size() && task_.obstacles[o].name != obstacleName) ++o;
  if (o == task_.obstacles.size()) throw std::invalid_argument("no obstacle named '" + obstacleName + "'");
  kinematics_.linkPoses(q, poses_);
  double best = std::numeric_limits<double>::infinity();
  for (int l : links) {
    if (l < 0 || static_cast<std::size_t>(l) >= g.links.size()) throw std::invalid_argument("link index out of range");
    best = std::min(best, linkObstacleDistance(l, o));
  }
  return best;
}

std::optional<Clearance> ExactCollisionChecker::clearance(const Configuration& q,
                                                          const std::optional<std::string>& obstacleName) {
  const auto& g = *geometry_;
  kinematics_.linkPoses(q, poses_);
  std::optional<Clearance> best;
  for (std::size_t o = 0; o < g.obstacles.size(); ++o) {
    if (obstacleName && task_.obstacles[o].name != *obstacleName) continue;
    for (std::size_t l = 0; l < g.links.size(); ++l) {
      if (g.links[l].empty()) continue;
      const double d = linkObstacleDistance(static_cast<int>(l), o);
      if (!best || d < best->metres) best = Clearance{d, {model_.links()[l].name, task_.obstacles[o].name}};
    }
  }
  return best;
}

}  // namespace pmdplan
