// The contact reference (support/contact_reference.hpp) against closed forms, near contact: its
// support-function search agrees with every closed form within 1e-9 m on both sides of touching,
// so the 0.01 mm the checkers are held to is four orders of magnitude above its error.
#include "support/contact_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

using reference::Solid;

constexpr double kAgreement = 1e-9;

Eigen::Isometry3d randomPose(RandomSource& random, const Eigen::Vector3d& at) {
  const Eigen::Quaterniond q(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1),
                             random.uniform(-1, 1));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = at;
  return pose;
}

Solid randomSolid(RandomSource& random, Solid::Kind kind, const Eigen::Vector3d& at) {
  Solid s;
  s.kind = kind;
  s.pose = randomPose(random, at);
  s.half = {random.uniform(0.005, 0.05), random.uniform(0.005, 0.05), random.uniform(0.005, 0.05)};
  s.radius = random.uniform(0.005, 0.04);
  s.halfLength = random.uniform(0.005, 0.06);
  return s;
}

/// Moves b along the line of centres until the closed form says it is `gap` from a.
void placeAt(const Solid& a, Solid& b, double gap, double (*closedForm)(const Solid&, const Solid&)) {
  const Eigen::Vector3d direction = (b.pose.translation() - a.pose.translation()).normalized();
  double low = 0.0, high = 1.0;  // distance of b's centre from a's along the line
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    b.pose.translation() = a.pose.translation() + middle * direction;
    (closedForm(a, b) < gap ? low : high) = middle;
  }
  b.pose.translation() = a.pose.translation() + high * direction;
}

double sphereClosedForm(const Solid& a, const Solid& sphere) {
  return reference::pointSignedDistance(a, sphere.pose.translation()) - sphere.radius;
}

double capsulesClosedForm(const Solid& a, const Solid& b) { return reference::signedDistance(a, b); }

TEST(ContactReference, TheSupportSearchEqualsTheClosedFormsNearContact) {
  RandomSource random(37);
  double worst = 0.0;
  int cases = 0;
  for (auto kind : {Solid::Kind::Box, Solid::Kind::Cylinder, Solid::Kind::Capsule, Solid::Kind::Sphere}) {
    for (int trial = 0; trial < 150; ++trial) {
      const Solid a = randomSolid(random, kind, Eigen::Vector3d::Zero());
      Solid sphere = randomSolid(random, Solid::Kind::Sphere,
                                 Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)));
      const double gap = random.uniform(-0.003, 0.003);
      placeAt(a, sphere, gap, sphereClosedForm);
      const double closed = reference::signedDistance(a, sphere);
      const double searched = reference::supportSignedDistance(a, sphere).metres;
      ASSERT_NEAR(closed, gap, 1e-12);
      EXPECT_NEAR(searched, closed, kAgreement) << "kind " << static_cast<int>(kind) << " trial " << trial;
      worst = std::max(worst, std::abs(searched - closed));
      ++cases;
    }
  }
  for (int trial = 0; trial < 300; ++trial) {
    const Solid a = randomSolid(random, Solid::Kind::Capsule, Eigen::Vector3d::Zero());
    Solid b = randomSolid(random, Solid::Kind::Capsule,
                          Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)));
    placeAt(a, b, random.uniform(-0.003, 0.003), capsulesClosedForm);
    const double closed = reference::signedDistance(a, b);
    const double searched = reference::supportSignedDistance(a, b).metres;
    // Two crossing segments' Minkowski difference is flat: the depth is the radii, found exactly.
    EXPECT_NEAR(searched, closed, kAgreement) << "capsules, trial " << trial;
    worst = std::max(worst, std::abs(searched - closed));
    ++cases;
  }
  std::printf("[ reference ] %d near-contact pairs: support search vs closed form, worst %.3g m\n", cases, worst);
}

// Two boxes (and a box and a cylinder) in one frame turned at random: their distance and depth
// are known without the reference (the gaps along the shared axes).
TEST(ContactReference, AlignedBoxesAndCylindersHaveTheirKnownDistanceAndDepth) {
  RandomSource random(38);
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Isometry3d frame = randomPose(random, Eigen::Vector3d::Zero());
    Solid a = randomSolid(random, Solid::Kind::Box, Eigen::Vector3d::Zero());
    Solid b = randomSolid(random, Solid::Kind::Box, Eigen::Vector3d::Zero());
    a.pose = frame;
    const int axis = trial % 3;
    const double gap = random.uniform(-0.003, 0.003);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    offset[axis] = a.half[axis] + b.half[axis] + gap;
    // A small sideways offset keeps the faces overlapping in the other two axes.
    offset[(axis + 1) % 3] = 0.2 * std::min(a.half[(axis + 1) % 3], b.half[(axis + 1) % 3]);
    b.pose = frame * Eigen::Translation3d(offset);
    const double expected = gap >= 0 ? gap : std::max({gap, -(a.half + b.half - offset.cwiseAbs()).minCoeff()});
    EXPECT_NEAR(reference::signedDistance(a, b), expected, kAgreement) << "boxes, trial " << trial;

    // A cylinder standing on the box's face (its axis along `axis`), by `gap`.
    Solid cylinder = randomSolid(random, Solid::Kind::Cylinder, Eigen::Vector3d::Zero());
    cylinder.radius = 0.3 * std::min(a.half[(axis + 1) % 3], a.half[(axis + 2) % 3]);
    Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
    if (axis != 2)
      turn.linear() = Eigen::AngleAxisd(M_PI / 2, axis == 0 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX())
                          .toRotationMatrix();
    Eigen::Vector3d along = Eigen::Vector3d::Zero();
    along[axis] = a.half[axis] + cylinder.halfLength + gap;
    cylinder.pose = frame * Eigen::Translation3d(along) * turn;
    const double depthLimit = std::min(2 * cylinder.halfLength, 2 * a.half[axis]);
    EXPECT_NEAR(reference::signedDistance(a, cylinder), std::max(gap, -depthLimit), kAgreement)
        << "box and cylinder, trial " << trial;
  }
}

// The hull of a mesh: a tessellated box is the box.
TEST(ContactReference, AMeshIsTheHullOfItsVertices) {
  RandomSource random(39);
  for (int trial = 0; trial < 100; ++trial) {
    Solid box = randomSolid(random, Solid::Kind::Box, Eigen::Vector3d::Zero());
    Solid mesh = box;
    mesh.kind = Solid::Kind::Mesh;
    auto corners = std::make_shared<std::vector<Eigen::Vector3d>>();
    for (int corner = 0; corner < 8; ++corner)
      corners->emplace_back((corner & 1 ? 1 : -1) * box.half.x(), (corner & 2 ? 1 : -1) * box.half.y(),
                            (corner & 4 ? 1 : -1) * box.half.z());
    mesh.vertices = corners;
    Solid other = randomSolid(random, trial % 2 ? Solid::Kind::Cylinder : Solid::Kind::Capsule,
                              Eigen::Vector3d(random.uniform(-0.06, 0.06), random.uniform(-0.06, 0.06), 0.05));
    EXPECT_NEAR(reference::signedDistance(mesh, other), reference::signedDistance(box, other), kAgreement);
  }
}

}  // namespace
}  // namespace pmdplan
