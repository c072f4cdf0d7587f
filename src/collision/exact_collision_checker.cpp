#include "pmdplan/collision/exact_collision_checker.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "fcl_geometry.hpp"
#include "mesh_containment.hpp"
#include "urdf_capsules.hpp"

namespace pmdplan {

struct PlacedGeometry {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  Eigen::Isometry3d pose;         ///< in the link frame (robot) or the world (obstacles)
  double radius = 0.0;            ///< encloses the geometry around pose.translation()
  bool againstBoxesOnly = false;  ///< a URDF capsule's second form (see the constructor)
  /// A point of the geometry (in its frame): a primitive's centre, a mesh's first vertex.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::shared_ptr<const MeshInterior> interior;  ///< meshes: what is inside them
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
  std::vector<std::vector<PlacedGeometry>> links;  ///< per link
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

bool shapesCollide(const PlacedGeometry& a, const Eigen::Isometry3d& poseA, const PlacedGeometry& b,
                   const Eigen::Isometry3d& poseB, const fcl::CollisionRequestd& request) {
  if ((a.againstBoxesOnly && b.geometry->getNodeType() != fcl::GEOM_BOX) ||
      (b.againstBoxesOnly && a.geometry->getNodeType() != fcl::GEOM_BOX))
    return false;
  if (spheresApart(poseA.translation(), a.radius, poseB.translation(), b.radius)) return false;
  fcl::CollisionResultd result;
  fcl::collide(a.geometry.get(), poseA, b.geometry.get(), poseB, request, result);
  if (result.isCollision()) return true;
  // No triangle touched: one wholly inside the other mesh (mesh_containment.hpp)?
  return (b.interior && b.interior->contains(poseB.inverse() * (poseA * a.point))) ||
         (a.interior && a.interior->contains(poseA.inverse() * (poseB * b.point)));
}

/// Geometry for `shape` placed at `pose`, with its point and, for a mesh, its interior.
PlacedGeometry placedGeometry(const Shape& shape, const Eigen::Isometry3d& pose) {
  PlacedGeometry placed{makeFclGeometry(shape), pose};
  placed.radius = enclosingRadius(shape, *placed.geometry);
  if (const auto* mesh = std::get_if<MeshShape>(&shape)) {
    auto triangles =
        mesh->triangles ? mesh->triangles : std::make_shared<const TriangleMesh>(readMeshFile(mesh->file, mesh->scale));
    placed.point = triangles->vertices[triangles->triangles.front()[0]];
    placed.interior = std::make_shared<const MeshInterior>(std::move(triangles));
  }
  return placed;
}

/// Distance between two shapes, or minus their penetration depth when they overlap. Whether they
/// overlap is the collision test's answer; the depth is FCL's signed distance, which only its
/// libccd solver computes (EPA) for these shapes; a depth it misses counts as touching (0).
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
    // Against boxes, a URDF capsule (a cylinder capped by two spheres of its radius) goes to FCL
    // as one capsule too. The union is the same solid, but FCL 0.7 (GJK, GST_INDEP) misses some
    // contacts of a box with a cylinder, and others of a box with a capsule: asked both ways it
    // misses neither kind (the fast checker's equivalence tests, which decide these pairs
    // geometrically, found both).
    for (const UrdfCapsule& capsule : urdfCapsules(shapes)) {
      if (capsule.capA < 0) continue;
      const PlacedShape& cylinder = shapes[static_cast<std::size_t>(capsule.cylinder)];
      const double length = std::get<CylinderShape>(cylinder.shape).length;
      auto geometry = std::make_shared<fcl::Capsuled>(capsule.radius, length);
      geometry->computeLocalAABB();
      g.links[l].push_back({geometry, cylinder.pose, 0.5 * length + capsule.radius, true});
    }
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

bool ExactCollisionChecker::linkPairCollides(const LinkPoses& poses, int a, int b) const {
  const auto& g = *geometry_;
  const auto& pa = poses[static_cast<std::size_t>(a)];
  const auto& pb = poses[static_cast<std::size_t>(b)];
  const auto& sa = g.linkSpheres[static_cast<std::size_t>(a)];
  const auto& sb = g.linkSpheres[static_cast<std::size_t>(b)];
  if (spheresApart(pa * sa.centre, sa.radius, pb * sb.centre, sb.radius)) return false;
  for (const auto& shapeA : g.links[static_cast<std::size_t>(a)])
    for (const auto& shapeB : g.links[static_cast<std::size_t>(b)])
      if (shapesCollide(shapeA, pa * shapeA.pose, shapeB, pb * shapeB.pose, g.request)) return true;
  return false;
}

bool ExactCollisionChecker::linkObstacleCollides(const LinkPoses& poses, int link, std::size_t o) const {
  const auto& g = *geometry_;
  const auto l = static_cast<std::size_t>(link);
  if (g.links[l].empty()) return false;
  const auto& pose = poses[l];
  const auto& obstacle = g.obstacles[o];
  if (sphereOutsideBox(pose * g.linkSpheres[l].centre, g.linkSpheres[l].radius, obstacle)) return false;
  return std::any_of(g.links[l].begin(), g.links[l].end(), [&](const PlacedGeometry& shape) {
    const Eigen::Isometry3d shapePose = pose * shape.pose;
    return !sphereOutsideBox(shapePose.translation(), shape.radius, obstacle) &&
           shapesCollide(shape, shapePose, obstacle, obstacle.pose, g.request);
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
    for (const auto& shape : g.links[static_cast<std::size_t>(l)]) {
      fcl::DistanceResultd result;
      fcl::distance(shape.geometry.get(), poses_[static_cast<std::size_t>(l)] * shape.pose,
                    g.obstacles[o].geometry.get(), g.obstacles[o].pose, g.distanceRequest, result);
      best = std::min(best, result.min_distance);
    }
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
    for (std::size_t l = 0; l < g.links.size(); ++l)
      for (const auto& shape : g.links[l]) {
        // A capsule's second form is asked against boxes only, as in the collision test.
        if (shape.againstBoxesOnly && g.obstacles[o].geometry->getNodeType() != fcl::GEOM_BOX) continue;
        const double d = signedDistance(shape, poses_[l] * shape.pose, g.obstacles[o], g.obstacles[o].pose, g.request,
                                        g.distanceRequest);
        if (!best || d < best->metres) best = Clearance{d, {model_.links()[l].name, task_.obstacles[o].name}};
      }
  }
  return best;
}

}  // namespace pmdplan
