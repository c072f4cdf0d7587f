// The sphere model encloses every collision primitive completely: points sampled in and on every
// primitive of the SAH/TX90 robot (and of shapes the robot does not have: flat boxes, disks,
// huge boxes at the sphere limit) lie in the union of the covering spheres, in the group's
// capsule or box, and in the group's and link's bounding spheres.
#include "pmdplan/collision/link_sphere_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "collision/task_configurations.hpp"
#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

constexpr double kRounding = 1e-12;

/// A point in or on the shape (in its own frame): half the draws on the surface.
Eigen::Vector3d samplePoint(const Shape& shape, RandomSource& random) {
  const bool surface = random.uniform01() < 0.5;
  if (const auto* box = std::get_if<BoxShape>(&shape)) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p[a] = random.uniform(-0.5, 0.5) * box->size[a];
    if (surface) {
      const int axis = static_cast<int>(random.uniform01() * 3.0);
      p[axis] = (random.uniform01() < 0.5 ? -0.5 : 0.5) * box->size[axis];
    }
    return p;
  }
  if (const auto* cylinder = std::get_if<CylinderShape>(&shape)) {
    const double angle = random.uniform(0.0, 6.283185307179586);
    double rho = cylinder->radius * std::sqrt(random.uniform01());
    double z = random.uniform(-0.5, 0.5) * cylinder->length;
    if (surface && random.uniform01() < 0.5)
      rho = cylinder->radius;
    else if (surface)
      z = (random.uniform01() < 0.5 ? -0.5 : 0.5) * cylinder->length;
    return {rho * std::cos(angle), rho * std::sin(angle), z};
  }
  const double r = std::get<SphereShape>(shape).radius;
  Eigen::Vector3d direction(testing::normal(random), testing::normal(random), testing::normal(random));
  direction.normalize();
  return direction * (surface ? r : r * std::cbrt(random.uniform01()));
}

bool inSphere(const Sphere& s, const Eigen::Vector3d& p) {
  return (p - Eigen::Vector3d(s.centre[0], s.centre[1], s.centre[2])).norm() <= s.radius + kRounding;
}

TEST(LinkSphereModel, EveryPrimitiveOfTheRobotLiesInItsSpheresCapsulesBoxesAndBounds) {
  const RobotModel model = RobotModel::loadBuiltIn("sah_tx90");
  for (const double margin : {0.0, 1e-5}) {
    SphereCoverParameters parameters;
    parameters.safetyMargin = margin;
    const LinkSphereModel spheres(model, parameters);
    RandomSource random(11);
    for (std::size_t l = 0; l < model.links().size(); ++l) {
      const auto& link = spheres.links()[l];
      ASSERT_EQ(link.empty(), model.links()[l].collisionShapes.empty());
      for (const auto& placed : model.links()[l].collisionShapes)
        for (int trial = 0; trial < 4000; ++trial) {
          const Eigen::Vector3d p = placed.pose * samplePoint(placed.shape, random);
          ASSERT_TRUE(inSphere(link.bound, p)) << model.links()[l].name;
          // Some group must contain the point in all its representations.
          bool covered = false;
          for (int g = 0; g < link.groupCount() && !covered; ++g) {
            bool inUnion = false;
            for (int i = link.groupBegin[static_cast<std::size_t>(g)]; i < link.groupBegin[static_cast<std::size_t>(g) + 1]; ++i)
              inUnion = inUnion || inSphere(Sphere{{link.x[static_cast<std::size_t>(i)], link.y[static_cast<std::size_t>(i)],
                                                    link.z[static_cast<std::size_t>(i)]}, link.radius[static_cast<std::size_t>(i)]}, p);
            if (!inUnion || !inSphere(link.groupBounds[static_cast<std::size_t>(g)], p)) continue;
            const auto kind = link.groupKind[static_cast<std::size_t>(g)];
            if (kind == GroupKind::Capsule) {
              const Capsule& c = link.groupCapsules[static_cast<std::size_t>(g)];
              if (segmentDistance(p.data(), p.data(), c.a, c.b) > c.radius + kRounding) continue;
            } else if (kind == GroupKind::Box) {
              if (sphereGap(link.groupBoxes[static_cast<std::size_t>(g)], p.x(), p.y(), p.z(), 0.0) > kRounding) continue;
            }
            covered = true;
          }
          ASSERT_TRUE(covered) << model.links()[l].name << " point " << p.transpose() << " margin " << margin;
        }
    }
  }
}

TEST(LinkSphereModel, CoversShapesOfEveryProportionWithinTheOvershoot) {
  const std::vector<Shape> shapes = {BoxShape{Eigen::Vector3d(0.3, 0.01, 0.2)}, BoxShape{Eigen::Vector3d(2.0, 2.0, 0.02)},
                                     CylinderShape{0.05, 0.004}, CylinderShape{0.01, 0.5}, SphereShape{0.02}};
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.1, -0.2, 0.3);
  SphereCoverParameters parameters;
  parameters.safetyMargin = 0.0;
  RandomSource random(3);
  for (const auto& shape : shapes) {
    const auto spheres = coverShape(shape, pose, parameters);
    ASSERT_FALSE(spheres.empty());
    EXPECT_LE(static_cast<int>(spheres.size()), parameters.maxSpheresPerShape);
    for (int trial = 0; trial < 20000; ++trial) {
      const Eigen::Vector3d p = pose * samplePoint(shape, random);
      bool inside = false;
      for (const auto& s : spheres) inside = inside || inSphere(s, p);
      ASSERT_TRUE(inside) << "shape " << shape.index() << " point " << p.transpose();
    }
  }
  EXPECT_THROW(coverShape(MeshShape{"x.stl", Eigen::Vector3d::Ones()}, pose, parameters), std::invalid_argument);
  parameters.maxOvershoot = 0.0;
  EXPECT_THROW(coverShape(SphereShape{0.02}, pose, parameters), std::invalid_argument);
}

TEST(LinkSphereModel, SmallBoxesMeetTheOvershootAndCapsulesAbsorbTheirEndSpheres) {
  SphereCoverParameters parameters;
  parameters.safetyMargin = 0.0;
  // A phalanx pad, with room for enough spheres: every sphere pokes out of the box by at most the
  // overshoot. (With the default limit of 64 it gets a coarser grid.)
  parameters.maxSpheresPerShape = 1000;
  const BoxShape pad{Eigen::Vector3d(0.052, 0.02, 0.02)};
  const auto padSpheres = coverShape(pad, Eigen::Isometry3d::Identity(), parameters);
  EXPECT_GT(padSpheres.size(), 64u);
  for (const auto& s : padSpheres) {
    double poke = 0.0;
    for (int a = 0; a < 3; ++a) poke = std::max(poke, std::abs(s.centre[a]) + s.radius - 0.5 * pad.size[a]);
    EXPECT_LE(poke, parameters.maxOvershoot + 1e-12);
  }
  // The SAH phalanges are cylinder + two end spheres: one capsule group per phalanx and one box.
  const RobotModel model = RobotModel::loadBuiltIn("sah_tx90");
  const LinkSphereModel spheres(model, SphereCoverParameters{});
  const auto& proximal = spheres.links()[static_cast<std::size_t>(model.linkIndex("index_proximal_link"))];
  ASSERT_EQ(proximal.groupCount(), 2);
  EXPECT_EQ(proximal.groupKind[0], GroupKind::Capsule);
  EXPECT_EQ(proximal.groupKind[1], GroupKind::Box);
  EXPECT_NEAR(proximal.groupCapsules[0].radius, 0.0115 + SphereCoverParameters{}.safetyMargin, 1e-9);
}

}  // namespace
}  // namespace pmdplan
