// The narrow phase's distances against FCL and brute force: segment and sphere distances are
// exact; GJK's bounds on the distance between random boxes, cylinders, capsules and spheres hold
// against FCL's own estimate and close in on each other; partContact never calls two parts apart or overlapping against
// FCL's answer.
#include "pmdplan/collision/fast/convex_distance.hpp"

#include <fcl/fcl.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

Eigen::Matrix3d randomRotation(RandomSource& random) {
  // One draw per statement: the order in which a call's arguments are evaluated is the compiler's
  // (GCC right to left, clang left to right), and the parts must be the same under both.
  const double z = random.uniform(-1, 1), y = random.uniform(-1, 1), x = random.uniform(-1, 1);
  const Eigen::Vector3d axis(x, y, z);
  return Eigen::AngleAxisd(random.uniform(0, 6.3), axis.normalized()).toRotationMatrix();
}

/// A random part near the origin and the same solid for FCL (a capsule as FCL's capsule).
struct TestPart {
  ConvexPart part;
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

TestPart randomPart(RandomSource& random, int kind, double spread) {
  TestPart t;
  t.pose.linear() = randomRotation(random);
  for (int i = 0; i < 3; ++i) t.pose.translation()[i] = random.uniform(-spread, spread);
  double pose[12];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose[r * 3 + c] = t.pose.linear()(r, c);
    pose[9 + r] = t.pose.translation()[r];
  }
  if (kind == 0) {
    const double half[3] = {random.uniform(0.005, 0.08), random.uniform(0.005, 0.08), random.uniform(0.005, 0.08)};
    t.part = boxPart(pose, half);
    t.geometry = std::make_shared<fcl::Boxd>(2 * half[0], 2 * half[1], 2 * half[2]);
  } else if (kind == 1) {
    const double radius = random.uniform(0.005, 0.06), half = random.uniform(0.002, 0.08);
    t.part = cylinderPart(pose, radius, half);
    t.geometry = std::make_shared<fcl::Cylinderd>(radius, 2 * half);
  } else {
    const double radius = random.uniform(0.005, 0.04), half = kind == 2 ? random.uniform(0.005, 0.08) : 0.0;
    const Eigen::Vector3d a = t.pose * Eigen::Vector3d(0, 0, -half), b = t.pose * Eigen::Vector3d(0, 0, half);
    const double pa[3] = {a.x(), a.y(), a.z()}, pb[3] = {b.x(), b.y(), b.z()};
    t.part = capsulePart(pa, pb, radius);
    if (half > 0.0)
      t.geometry = std::make_shared<fcl::Capsuled>(radius, 2 * half);
    else
      t.geometry = std::make_shared<fcl::Sphered>(radius);
  }
  return t;
}

double fclDistance(const TestPart& a, const TestPart& b) {
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  fcl::DistanceResultd result;
  fcl::distance(a.geometry.get(), a.pose, b.geometry.get(), b.pose, request, result);
  return result.min_distance;
}

bool fclCollide(const TestPart& a, const TestPart& b) {
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  fcl::CollisionResultd result;
  fcl::collide(a.geometry.get(), a.pose, b.geometry.get(), b.pose, request, result);
  return result.isCollision();
}

TEST(ConvexDistance, SegmentDistanceEqualsTheSampledMinimum) {
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

TEST(ConvexDistance, TheLaneSegmentDistancesEqualTheScalarOne) {
  RandomSource random(3);
  constexpr int L = kSegmentLanes;
  for (int trial = 0; trial < 2000; ++trial) {
    double p0[3 * L], p1[3 * L], q0[3 * L], q1[3 * L], lanes[L];
    for (int l = 0; l < L; ++l)
      for (int i = 0; i < 3; ++i) {
        p0[i * L + l] = random.uniform(-0.1, 0.1), p1[i * L + l] = random.uniform(-0.1, 0.1);
        q0[i * L + l] = random.uniform(-0.1, 0.1), q1[i * L + l] = random.uniform(-0.1, 0.1);
        // Points and parallel segments too: every branch of the scalar version.
        if ((trial + l) % 5 == 0) p1[i * L + l] = p0[i * L + l];
        if ((trial + l) % 7 == 0) q1[i * L + l] = q0[i * L + l];
        if ((trial + l) % 11 == 0) q1[i * L + l] = q0[i * L + l] + (p1[i * L + l] - p0[i * L + l]);
      }
    segmentDistances(p0, p1, q0, q1, lanes);
    for (int l = 0; l < L; ++l) {
      const double a[3] = {p0[l], p0[L + l], p0[2 * L + l]}, b[3] = {p1[l], p1[L + l], p1[2 * L + l]};
      const double c[3] = {q0[l], q0[L + l], q0[2 * L + l]}, d[3] = {q1[l], q1[L + l], q1[2 * L + l]};
      ASSERT_NEAR(lanes[l], segmentDistance(a, b, c, d), 1e-15) << "trial " << trial << " lane " << l;
    }
  }
}

TEST(ConvexDistance, SphereGapsAreExactForEveryKind) {
  const double identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  const ConvexPart cylinder = cylinderPart(identity, 0.1, 0.2);
  const auto gap = [](const ConvexPart& p, double x, double y, double z, double r) {
    const double c[3] = {x, y, z};
    return sphereGap(p, c, r);
  };
  EXPECT_NEAR(gap(cylinder, 0.5, 0.0, 0.0, 0.1), 0.3, 1e-15);  // beside the side
  EXPECT_NEAR(gap(cylinder, 0.0, 0.0, 0.5, 0.1), 0.2, 1e-15);  // above the cap
  EXPECT_NEAR(gap(cylinder, 0.4, 0.0, 0.6, 0.0), 0.5, 1e-15);  // beyond the rim: (0.3, 0.4)
  EXPECT_LE(gap(cylinder, 0.0, 0.0, 0.0, 0.01), 0.0);          // inside
  const double centre[3] = {0, 0, 0};
  const ConvexPart ball = capsulePart(centre, centre, 0.1);
  EXPECT_NEAR(gap(ball, 0.0, 0.3, 0.4, 0.1), 0.3, 1e-15);
  const double half[3] = {0.1, 0.2, 0.3};
  const ConvexPart box = boxPart(identity, half);
  EXPECT_NEAR(gap(box, 0.4, 0.6, 0.0, 0.1), 0.4, 1e-15);  // beyond an edge: (0.3, 0.4) - 0.1
  // The vectorised pass gives the same numbers.
  double x[3] = {0.5, 0.0, 0.4}, y[3] = {0, 0, 0}, z[3] = {0, 0.5, 0.6}, r[3] = {0.1, 0.1, 0.0};
  double gaps[3];
  for (const ConvexPart* p : {&cylinder, &ball, &box}) {
    sphereGaps(*p, x, y, z, r, 3, gaps);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(gaps[i], gap(*p, x[i], y[i], z[i], r[i]), 1e-15);
  }
}

/// The distance from a capsule's axis (a point or segment) to a box or cylinder, by golden-section
/// search along the axis: the exact point distance is convex along it.
double axisDistance(const ConvexPart& capsule, const ConvexPart& solid) {
  const auto at = [&](double t) {
    const double p[3] = {capsule.a[0] + t * (capsule.b[0] - capsule.a[0]),
                         capsule.a[1] + t * (capsule.b[1] - capsule.a[1]),
                         capsule.a[2] + t * (capsule.b[2] - capsule.a[2])};
    return sphereGap(solid, p, 0.0);
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) * 0.381966011250105, m2 = hi - (hi - lo) * 0.381966011250105;
    (at(m1) <= at(m2) ? hi : lo) = at(m1) <= at(m2) ? m2 : m1;
  }
  return std::min({at(0.0), at(1.0), at(0.5 * (lo + hi))});
}

TEST(ConvexDistance, GjkBoundsHoldForEveryPairOfKinds) {
  RandomSource random(4);
  int separated = 0, intersecting = 0, exactReferences = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const TestPart a = randomPart(random, trial % 4, 0.1), b = randomPart(random, (trial / 4) % 4, 0.1);
    const CoreDistance d = coreDistance(a.part, b.part, 0.0, 0.0, 1e-7);
    const bool collides = fclCollide(a, b);
    if (d.intersecting) {
      ++intersecting;
      EXPECT_TRUE(collides) << "trial " << trial;
      continue;
    }
    ASSERT_LE(d.lower, d.upper + 1e-15);
    EXPECT_LE(d.upper - d.lower, 1e-7 * d.lower + 1e-9) << "trial " << trial;  // converged
    const double radii = a.part.radius + b.part.radius;
    if (d.lower - radii > 1e-6) {
      ++separated;
      EXPECT_FALSE(collides) << "trial " << trial;
    } else if (d.upper - radii < -1e-6) {
      EXPECT_TRUE(collides) << "trial " << trial;
    }
    const bool capsuleA = a.part.kind == ConvexPart::Kind::Capsule, capsuleB = b.part.kind == ConvexPart::Kind::Capsule;
    if (capsuleA != capsuleB) {
      // A point or segment against a box or cylinder: an exact reference.
      const double reference = capsuleA ? axisDistance(a.part, b.part) : axisDistance(b.part, a.part);
      ++exactReferences;
      EXPECT_LE(d.lower, reference + 1e-12) << "trial " << trial;
      EXPECT_NEAR(d.upper, reference, 1e-7 * reference + 1e-9) << "trial " << trial;
    } else if (d.lower - radii > 1e-6) {
      // Otherwise FCL's estimate, the upper bound its own GJK stops at (up to 1 % above ours).
      const double fcl = fclDistance(a, b);
      EXPECT_LE(d.lower - radii, fcl + 1e-9) << "trial " << trial;
      EXPECT_NEAR(d.upper - radii, fcl, 2e-2 * fcl + 3e-5) << "trial " << trial;
    }
  }
  EXPECT_GT(separated, 1000);
  EXPECT_GT(intersecting, 200);
  EXPECT_GT(exactReferences, 1000);
}

TEST(ConvexDistance, PartContactAgreesWithFclWheneverItDecides) {
  RandomSource random(9);
  int apart = 0, overlapping = 0, uncertain = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const TestPart a = randomPart(random, trial % 4, 0.08), b = randomPart(random, (trial / 4) % 4, 0.08);
    const PartContact contact = partContact(a.part, b.part, 2e-5);
    const bool collides = fclCollide(a, b);
    if (contact.contact == Contact::Apart) {
      ++apart;
      EXPECT_FALSE(collides) << "trial " << trial;
      EXPECT_LE(contact.gap, fclDistance(a, b) + 1e-7) << "trial " << trial;
    } else if (contact.contact == Contact::Overlapping) {
      ++overlapping;
      EXPECT_TRUE(collides) << "trial " << trial;
    } else {
      ++uncertain;
    }
  }
  EXPECT_GT(apart, 1000);
  EXPECT_GT(overlapping, 1000);
  EXPECT_LT(uncertain, 60);  // only pairs within the band of touching
}

TEST(ConvexDistance, TouchingBoxesAreUncertainAndDeeperOnesOverlap) {
  const double identity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  const double half[3] = {0.05, 0.05, 0.05};
  const ConvexPart a = boxPart(identity, half);
  for (const auto& [offset, expected] :
       {std::pair{0.1 + 1e-6, Contact::Uncertain}, std::pair{0.1 - 1e-6, Contact::Uncertain},
        std::pair{0.1 - 1e-3, Contact::Overlapping}, std::pair{0.1 + 1e-3, Contact::Apart}}) {
    double pose[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, offset, 0.01, 0.0};
    EXPECT_EQ(partContact(a, boxPart(pose, half), 2e-5).contact, expected) << offset;
  }
}

}  // namespace
}  // namespace pmdplan
