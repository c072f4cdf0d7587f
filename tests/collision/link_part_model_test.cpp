// The convex parts are the robot's URDF geometry, no more and no less: every point sampled in or on
// a link's primitives lies in one of its parts, every point sampled in a part lies in one of the
// primitives, and the link's and each part's bounding sphere contain the part.
#include "pmdplan/collision/link_part_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "collision/task_configurations.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"
#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

constexpr double kRounding = 1e-12;

ConvexPart partOfShape(const PlacedShape& placed) {
  double pose[12];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose[r * 3 + c] = placed.pose.linear()(r, c);
    pose[9 + r] = placed.pose.translation()(r);
  }
  if (const auto* box = std::get_if<BoxShape>(&placed.shape)) {
    const double half[3] = {0.5 * box->size.x(), 0.5 * box->size.y(), 0.5 * box->size.z()};
    return boxPart(pose, half);
  }
  if (const auto* cylinder = std::get_if<CylinderShape>(&placed.shape))
    return cylinderPart(pose, cylinder->radius, 0.5 * cylinder->length);
  return capsulePart(pose + 9, pose + 9, std::get<SphereShape>(placed.shape).radius);
}

/// A point in or on the part (half the draws on its boundary).
Eigen::Vector3d samplePoint(const ConvexPart& part, RandomSource& random) {
  const bool surface = random.uniform01() < 0.5;
  if (part.kind == ConvexPart::Kind::Capsule) {
    const double t = random.uniform01();
    Eigen::Vector3d direction(testing::normal(random), testing::normal(random), testing::normal(random));
    direction.normalize();
    const double r = surface ? part.radius : part.radius * std::cbrt(random.uniform01());
    Eigen::Vector3d p;
    for (int i = 0; i < 3; ++i) p[i] = part.a[i] + t * (part.b[i] - part.a[i]) + r * direction[i];
    return p;
  }
  Eigen::Vector3d local;
  if (part.kind == ConvexPart::Kind::Box) {
    for (int a = 0; a < 3; ++a) local[a] = random.uniform(-1.0, 1.0) * part.half[a];
    if (surface) {
      const int axis = static_cast<int>(random.uniform01() * 3.0);
      local[axis] = (random.uniform01() < 0.5 ? -1.0 : 1.0) * part.half[axis];
    }
  } else {
    const double angle = random.uniform(0.0, 6.283185307179586);
    const double rho = surface ? part.half[0] : part.half[0] * std::sqrt(random.uniform01());
    local = {rho * std::cos(angle), rho * std::sin(angle), random.uniform(-1.0, 1.0) * part.half[1]};
  }
  Eigen::Vector3d p;
  for (int r = 0; r < 3; ++r)
    p[r] = part.a[r] + part.axes[r * 3] * local[0] + part.axes[r * 3 + 1] * local[1] + part.axes[r * 3 + 2] * local[2];
  return p;
}

bool inAny(const std::vector<ConvexPart>& parts, const Eigen::Vector3d& p) {
  const double c[3] = {p.x(), p.y(), p.z()};
  for (const auto& part : parts)
    if (sphereGap(part, c, 0.0) <= kRounding) return true;
  return false;
}

TEST(LinkPartModel, TheRobotsPartsAreExactlyItsPrimitives) {
  const RobotModel model = RobotModel::loadBuiltIn("sah_tx90");
  const auto links = linkParts(model);
  ASSERT_EQ(links.size(), model.links().size());
  RandomSource random(11);
  int capsules = 0;
  for (std::size_t l = 0; l < links.size(); ++l) {
    const auto& shapes = model.links()[l].collisionShapes;
    ASSERT_EQ(links[l].empty(), shapes.empty()) << model.links()[l].name;
    std::vector<ConvexPart> primitives;
    for (const auto& placed : shapes) primitives.push_back(partOfShape(placed));
    for (const auto& part : links[l].parts) {
      capsules += part.kind == ConvexPart::Kind::Capsule &&
                  (part.a[0] != part.b[0] || part.a[1] != part.b[1] || part.a[2] != part.b[2]);
      for (int s = 0; s < 2000; ++s) {
        const Eigen::Vector3d p = samplePoint(part, random);
        ASSERT_TRUE(inAny(primitives, p)) << model.links()[l].name << ": a part reaches beyond the URDF shapes";
        ASSERT_LE((p - Eigen::Vector3d(part.boundCentre[0], part.boundCentre[1], part.boundCentre[2])).norm(),
                  part.boundRadius + kRounding);
        ASSERT_LE(
            (p - Eigen::Vector3d(links[l].boundCentre[0], links[l].boundCentre[1], links[l].boundCentre[2])).norm(),
            links[l].boundRadius + kRounding);
      }
    }
    for (const auto& primitive : primitives)
      for (int s = 0; s < 2000; ++s)
        ASSERT_TRUE(inAny(links[l].parts, samplePoint(primitive, random)))
            << model.links()[l].name << ": a URDF shape is not covered";
  }
  // Cylinders capped by spheres at both ends are capsules: the proximal and medium phalanges and
  // five arm links (a distal phalanx has a sphere at its tip only: a cylinder and a sphere).
  EXPECT_EQ(capsules, 13);
}

TEST(LinkPartModel, ObstaclesAreExactPrimitivesOrAMeshsBox) {
  const Task task = loadTaskByName("t_in_clutter");
  const auto parts = obstacleParts(task.obstacles);
  ASSERT_EQ(parts.size(), task.obstacles.size());
  for (std::size_t o = 0; o < parts.size(); ++o) {
    EXPECT_EQ(parts[o].exact, !std::holds_alternative<MeshShape>(task.obstacles[o].shape));
    if (const auto* cylinder = std::get_if<CylinderShape>(&task.obstacles[o].shape)) {
      EXPECT_EQ(parts[o].part.kind, ConvexPart::Kind::Cylinder);
      EXPECT_DOUBLE_EQ(parts[o].part.half[0], cylinder->radius);
      EXPECT_DOUBLE_EQ(parts[o].part.half[1], 0.5 * cylinder->length);
    }
  }
}

}  // namespace
}  // namespace pmdplan
