// The primitive distances against brute force: exact sphere gaps and segment distances equal the
// smallest distance found by dense sampling, and the box and capsule-box lower bounds never
// exceed it (and are positive when the shapes are clearly apart).
#include "pmdplan/collision/primitive_distance.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

SolidPrimitive randomBox(RandomSource& random, double spread) {
  SolidPrimitive box;
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(random.uniform(0, 6.3), Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)).normalized())
          .toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    box.centre[i] = random.uniform(-spread, spread);
    box.size[i] = random.uniform(0.01, 0.1);
    for (int k = 0; k < 3; ++k) box.rotation[i * 3 + k] = r(i, k);
  }
  return box;
}

TEST(PrimitiveDistance, SegmentDistanceEqualsTheSampledMinimum) {
  RandomSource random(1);
  for (int trial = 0; trial < 300; ++trial) {
    double p[2][3], q[2][3];
    for (auto* end : {p[0], p[1], q[0], q[1]})
      for (int i = 0; i < 3; ++i) end[i] = random.uniform(-0.1, 0.1);
    if (trial % 3 == 0)
      for (int i = 0; i < 3; ++i) q[1][i] = q[0][i] + (p[1][i] - p[0][i]);  // parallel
    double best = 1e9;
    for (int a = 0; a <= 400; ++a)
      for (int b = 0; b <= 400; b += 4) {
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i) {
          const double x = p[0][i] + (p[1][i] - p[0][i]) * a / 400.0 - q[0][i] - (q[1][i] - q[0][i]) * b / 400.0;
          d2 += x * x;
        }
        best = std::min(best, std::sqrt(d2));
      }
    const double d = segmentDistance(p[0], p[1], q[0], q[1]);
    EXPECT_LE(d, best + 1e-12);
    EXPECT_GE(d, best - 2e-3);  // the sampling step
  }
  const double point[3] = {0, 0, 0}, a[3] = {1, 1, 0}, b[3] = {1, -1, 0};
  EXPECT_NEAR(segmentDistance(point, point, a, b), 1.0, 1e-15);
}

TEST(PrimitiveDistance, BoxBoundsNeverExceedTheDistanceBetweenSampledPoints) {
  RandomSource random(2);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const SolidPrimitive a = randomBox(random, 0.15), b = randomBox(random, 0.15);
    Capsule capsule;
    for (int i = 0; i < 3; ++i) capsule.a[i] = random.uniform(-0.15, 0.15), capsule.b[i] = random.uniform(-0.15, 0.15);
    capsule.radius = 0.01;
    const double boxes = boxGapLowerBound(a, b), capsuleBox = capsuleBoxGapLowerBound(capsule, a);
    separated += boxes > 0.0;
    for (int s = 0; s < 2000; ++s) {
      Eigen::Vector3d pa, pb;
      for (const auto& [box, point] : {std::pair{&a, &pa}, std::pair{&b, &pb}}) {
        Eigen::Vector3d local;
        for (int i = 0; i < 3; ++i) local[i] = random.uniform(-1, 1) * box->size[i];
        for (int i = 0; i < 3; ++i)
          (*point)[i] = box->centre[i] + box->rotation[i * 3] * local[0] + box->rotation[i * 3 + 1] * local[1] + box->rotation[i * 3 + 2] * local[2];
      }
      ASSERT_LE(boxes, (pa - pb).norm() + 1e-12);
      // A point of the capsule's axis against a point of box a, minus the radius.
      const double t = random.uniform01();
      Eigen::Vector3d axis;
      for (int i = 0; i < 3; ++i) axis[i] = capsule.a[i] + t * (capsule.b[i] - capsule.a[i]);
      ASSERT_LE(capsuleBox, (axis - pa).norm() - capsule.radius + 1e-12);
      // The exact sphere-box gap is a true distance too.
      ASSERT_LE(sphereGap(a, pb.x(), pb.y(), pb.z(), 0.0), (pa - pb).norm() + 1e-12);
    }
  }
  EXPECT_GT(separated, 30);
  // Two unit-aligned boxes 0.1 apart along x: the bound is exact.
  SolidPrimitive left, right;
  for (int i = 0; i < 3; ++i) left.size[i] = right.size[i] = 0.05;
  right.centre[0] = 0.2;
  EXPECT_NEAR(boxGapLowerBound(left, right), 0.1, 1e-15);
}

TEST(PrimitiveDistance, SphereGapsAreExactForEveryKind) {
  SolidPrimitive cylinder;
  cylinder.kind = SolidPrimitive::Kind::Cylinder;
  cylinder.size[0] = 0.1, cylinder.size[1] = 0.2;
  EXPECT_NEAR(sphereGap(cylinder, 0.5, 0.0, 0.0, 0.1), 0.3, 1e-15);   // beside the side
  EXPECT_NEAR(sphereGap(cylinder, 0.0, 0.0, 0.5, 0.1), 0.2, 1e-15);   // above the cap
  EXPECT_NEAR(sphereGap(cylinder, 0.4, 0.0, 0.6, 0.0), 0.5, 1e-15);   // beyond the rim: (0.3, 0.4)
  EXPECT_LE(sphereGap(cylinder, 0.0, 0.0, 0.0, 0.01), 0.0);           // inside
  SolidPrimitive ball;
  ball.kind = SolidPrimitive::Kind::Sphere;
  ball.size[0] = 0.1;
  EXPECT_NEAR(sphereGap(ball, 0.0, 0.3, 0.4, 0.1), 0.3, 1e-15);
  double x[3] = {0.5, 0.0, 0.4}, y[3] = {0, 0, 0}, z[3] = {0, 0.5, 0.6}, r[3] = {0.1, 0.1, 0.0};
  EXPECT_NEAR(smallestSphereGap(cylinder, x, y, z, r, 3), 0.2, 1e-15);
  double gaps[3];
  sphereGaps(cylinder, x, y, z, r, 3, gaps);
  EXPECT_NEAR(gaps[2], 0.5, 1e-15);
}

}  // namespace
}  // namespace pmdplan
