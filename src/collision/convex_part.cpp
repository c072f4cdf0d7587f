#include "pmdplan/collision/convex_part.hpp"

#include <algorithm>
#include <cmath>

namespace pmdplan {
namespace {

void transformPoint(const double* pose, const double* p, double* out) {
  for (int r = 0; r < 3; ++r)
    out[r] = pose[r * 3] * p[0] + pose[r * 3 + 1] * p[1] + pose[r * 3 + 2] * p[2] + pose[9 + r];
}

void setCentredBound(ConvexPart& part, const double* centre, double radius) {
  for (int i = 0; i < 3; ++i) part.boundCentre[i] = centre[i];
  // One ulp too small would let a point of the part poke out of its bound.
  part.boundRadius = radius * (1.0 + 1e-12);
}

/// The outer capsule along local axis k of a box or cylinder from -length to +length.
void setOuterCapsule(ConvexPart& part, int k, double length, double radius) {
  for (int r = 0; r < 3; ++r) {
    part.outerA[r] = part.a[r] - length * part.axes[r * 3 + k];
    part.outerB[r] = part.a[r] + length * part.axes[r * 3 + k];
  }
  part.outerRadius = radius * (1.0 + 1e-12);
}

}  // namespace

ConvexPart capsulePart(const double* a, const double* b, double radius) {
  ConvexPart part;
  part.kind = ConvexPart::Kind::Capsule;
  double middle[3], half2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    part.a[i] = a[i], part.b[i] = b[i];
    middle[i] = 0.5 * (a[i] + b[i]);
    half2 += 0.25 * (b[i] - a[i]) * (b[i] - a[i]);
  }
  part.radius = radius;
  setCentredBound(part, middle, std::sqrt(half2) + radius);
  for (int i = 0; i < 3; ++i) part.outerA[i] = a[i], part.outerB[i] = b[i];
  part.outerRadius = radius;
  return part;
}

ConvexPart boxPart(const double* pose, const double* halfExtents) {
  ConvexPart part;
  part.kind = ConvexPart::Kind::Box;
  for (int i = 0; i < 9; ++i) part.axes[i] = pose[i];
  for (int i = 0; i < 3; ++i) part.a[i] = pose[9 + i], part.half[i] = halfExtents[i];
  setCentredBound(
      part, part.a,
      std::sqrt(halfExtents[0] * halfExtents[0] + halfExtents[1] * halfExtents[1] + halfExtents[2] * halfExtents[2]));
  // Along the longest axis k every point is within the other two half extents of the axis.
  const int k = halfExtents[0] >= halfExtents[1] ? (halfExtents[0] >= halfExtents[2] ? 0 : 2)
                                                 : (halfExtents[1] >= halfExtents[2] ? 1 : 2);
  const double across2 = halfExtents[0] * halfExtents[0] + halfExtents[1] * halfExtents[1] +
                         halfExtents[2] * halfExtents[2] - halfExtents[k] * halfExtents[k];
  setOuterCapsule(part, k, halfExtents[k], std::sqrt(across2));
  return part;
}

ConvexPart cylinderPart(const double* pose, double radius, double halfLength) {
  ConvexPart part;
  part.kind = ConvexPart::Kind::Cylinder;
  for (int i = 0; i < 9; ++i) part.axes[i] = pose[i];
  for (int i = 0; i < 3; ++i) part.a[i] = pose[9 + i];
  part.half[0] = radius, part.half[1] = halfLength;
  setCentredBound(part, part.a, std::sqrt(radius * radius + halfLength * halfLength));
  setOuterCapsule(part, 2, halfLength, radius);
  return part;
}

ConvexPart trianglePart(const double* a, const double* b, const double* c) {
  ConvexPart part;
  part.kind = ConvexPart::Kind::Triangle;
  double centre[3];
  for (int i = 0; i < 3; ++i)
    part.a[i] = a[i], part.b[i] = b[i], part.c[i] = c[i], centre[i] = (a[i] + b[i] + c[i]) / 3;
  const auto distance = [](const double* p, const double* q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  };
  setCentredBound(part, centre, std::max({distance(centre, a), distance(centre, b), distance(centre, c)}));
  // The outer capsule: around the longest edge, as thick as the third corner's distance from it
  // (every point of the triangle is no farther from that edge than its corners).
  const double* corners[3] = {a, b, c};
  int longest = 0;
  for (int e = 1; e < 3; ++e)
    if (distance(corners[e], corners[(e + 1) % 3]) > distance(corners[longest], corners[(longest + 1) % 3]))
      longest = e;
  const double *p = corners[longest], *q = corners[(longest + 1) % 3], *r = corners[(longest + 2) % 3];
  double pq[3], pr[3], length2 = 0.0, along = 0.0;
  for (int i = 0; i < 3; ++i)
    pq[i] = q[i] - p[i], pr[i] = r[i] - p[i], length2 += pq[i] * pq[i], along += pq[i] * pr[i];
  const double t = length2 > 0.0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
  double across2 = 0.0;
  for (int i = 0; i < 3; ++i) across2 += (pr[i] - t * pq[i]) * (pr[i] - t * pq[i]);
  for (int i = 0; i < 3; ++i) part.outerA[i] = p[i], part.outerB[i] = q[i];
  part.outerRadius = std::sqrt(across2) * (1.0 + 1e-12);
  return part;
}

void placePart(const ConvexPart& local, const double* pose, ConvexPart& world) {
  world.kind = local.kind;
  world.enclosure = local.enclosure;
  world.radius = local.radius;
  for (int i = 0; i < 3; ++i) world.half[i] = local.half[i];
  transformPoint(pose, local.a, world.a);
  transformPoint(pose, local.boundCentre, world.boundCentre);
  world.boundRadius = local.boundRadius;
  transformPoint(pose, local.outerA, world.outerA);
  transformPoint(pose, local.outerB, world.outerB);
  world.outerRadius = local.outerRadius;
  if (local.kind == ConvexPart::Kind::Capsule || local.kind == ConvexPart::Kind::Triangle) {
    transformPoint(pose, local.b, world.b);
    if (local.kind == ConvexPart::Kind::Triangle) transformPoint(pose, local.c, world.c);
    return;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      world.axes[r * 3 + c] =
          pose[r * 3] * local.axes[c] + pose[r * 3 + 1] * local.axes[3 + c] + pose[r * 3 + 2] * local.axes[6 + c];
}

void coreSupport(const ConvexPart& part, const double* d, double* point) {
  if (part.kind == ConvexPart::Kind::Capsule) {
    const double along =
        d[0] * (part.b[0] - part.a[0]) + d[1] * (part.b[1] - part.a[1]) + d[2] * (part.b[2] - part.a[2]);
    const double* end = along > 0.0 ? part.b : part.a;
    for (int i = 0; i < 3; ++i) point[i] = end[i];
    return;
  }
  if (part.kind == ConvexPart::Kind::Triangle) {
    const double* best = part.a;
    double bestAlong = d[0] * part.a[0] + d[1] * part.a[1] + d[2] * part.a[2];
    for (const double* corner : {part.b, part.c})
      if (const double along = d[0] * corner[0] + d[1] * corner[1] + d[2] * corner[2]; along > bestAlong)
        best = corner, bestAlong = along;
    for (int i = 0; i < 3; ++i) point[i] = best[i];
    return;
  }
  const double* m = part.axes;
  // The direction in the part's own frame (rotation transposed).
  const double u = m[0] * d[0] + m[3] * d[1] + m[6] * d[2];
  const double v = m[1] * d[0] + m[4] * d[1] + m[7] * d[2];
  const double w = m[2] * d[0] + m[5] * d[1] + m[8] * d[2];
  double local[3];
  if (part.kind == ConvexPart::Kind::Box) {
    local[0] = u >= 0.0 ? part.half[0] : -part.half[0];
    local[1] = v >= 0.0 ? part.half[1] : -part.half[1];
    local[2] = w >= 0.0 ? part.half[2] : -part.half[2];
  } else {
    const double radial = std::sqrt(u * u + v * v);
    const double scale = radial > 0.0 ? part.half[0] / radial : 0.0;
    local[0] = u * scale, local[1] = v * scale;
    local[2] = w >= 0.0 ? part.half[1] : -part.half[1];
  }
  for (int r = 0; r < 3; ++r)
    point[r] = part.a[r] + m[r * 3] * local[0] + m[r * 3 + 1] * local[1] + m[r * 3 + 2] * local[2];
}

bool shrinkPart(const ConvexPart& part, double amount, ConvexPart& shrunk) {
  shrunk = part;
  switch (part.kind) {
    case ConvexPart::Kind::Capsule:
      shrunk.radius = part.radius - amount;
      return shrunk.radius >= 0.0;
    case ConvexPart::Kind::Box:
      for (double& h : shrunk.half) h -= amount;
      return std::min({shrunk.half[0], shrunk.half[1], shrunk.half[2]}) >= 0.0;
    case ConvexPart::Kind::Cylinder:
      shrunk.half[0] -= amount, shrunk.half[1] -= amount;
      return shrunk.half[0] >= 0.0 && shrunk.half[1] >= 0.0;
    case ConvexPart::Kind::Triangle:
      return false;
  }
  return false;
}

}  // namespace pmdplan
