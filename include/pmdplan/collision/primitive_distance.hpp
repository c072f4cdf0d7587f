#pragma once
// Distances between solid primitives in plain numbers, for the fast checker's inner loops: exact
// sphere-to-box / -cylinder / -sphere gaps, and a separating-axis lower bound between two boxes.
// A positive result means apart by at least that much; zero or less means touching or unknown.
#include <algorithm>
#include <cmath>
#include <limits>

namespace pmdplan {

/// A box, cylinder (along local z) or sphere placed in the world.
struct SolidPrimitive {
  enum class Kind { Box, Cylinder, Sphere } kind = Kind::Box;
  double centre[3] = {0, 0, 0};
  double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< row-major, local -> world (columns: local axes)
  /// Box: half extents; cylinder: radius, half length, 0; sphere: radius, 0, 0.
  double size[3] = {0, 0, 0};
};

/// A segment swept by a ball: every point within `radius` of the segment a-b (a sphere when a = b).
struct Capsule {
  double a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
  double radius = 0.0;
};

/// Distance between the segments p0-p1 and q0-q1 (either may be a point).
double segmentDistance(const double* p0, const double* p1, const double* q0, const double* q1);

/// Distance from the sphere (x, y, z, r) to the primitive: exact when positive.
[[gnu::always_inline]] inline double sphereGap(const SolidPrimitive& p, double x, double y, double z, double r) {
  const double dx = x - p.centre[0], dy = y - p.centre[1], dz = z - p.centre[2];
  const double* m = p.rotation;
  const double u = m[0] * dx + m[3] * dy + m[6] * dz;  // local coordinates: rotation transposed
  const double v = m[1] * dx + m[4] * dy + m[7] * dz;
  const double w = m[2] * dx + m[5] * dy + m[8] * dz;
  double outside2;
  if (p.kind == SolidPrimitive::Kind::Box) {
    const double ou = std::max(std::abs(u) - p.size[0], 0.0), ov = std::max(std::abs(v) - p.size[1], 0.0),
                 ow = std::max(std::abs(w) - p.size[2], 0.0);
    outside2 = ou * ou + ov * ov + ow * ow;
  } else if (p.kind == SolidPrimitive::Kind::Cylinder) {
    const double radial = std::max(std::sqrt(u * u + v * v) - p.size[0], 0.0), axial = std::max(std::abs(w) - p.size[1], 0.0);
    outside2 = radial * radial + axial * axial;
  } else {
    const double d = std::max(std::sqrt(u * u + v * v + w * w) - p.size[0], 0.0);
    outside2 = d * d;
  }
  return std::sqrt(outside2) - r;
}

/// Smallest gap of `count` spheres (centres x, y, z; radii r) to the primitive.
double smallestSphereGap(const SolidPrimitive& p, const double* x, const double* y, const double* z, const double* r, int count);

/// A lower bound on the distance between a capsule and a box: the largest gap between their
/// projections on the box's three face normals (<= 0 when those axes do not separate them).
double capsuleBoxGapLowerBound(const Capsule& capsule, const SolidPrimitive& box);

/// The gap of each of `count` spheres to the primitive, into gaps[i].
void sphereGaps(const SolidPrimitive& p, const double* x, const double* y, const double* z, const double* r, int count, double* gaps);

/// A lower bound on the distance between two boxes: the largest gap between their projections on
/// the 15 separating axes (face normals, then edge cross products only if no face separates).
/// Positive exactly when they are apart (the separating axis theorem), never more than their distance.
double boxGapLowerBound(const SolidPrimitive& a, const SolidPrimitive& b);

}  // namespace pmdplan
