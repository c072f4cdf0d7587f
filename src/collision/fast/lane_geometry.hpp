#pragma once
// The building blocks the pair kernels (one header per pair of part kinds, docs/architecture.md)
// share, lane by lane over lane vectors (lane_vector.hpp) of any width: the distance between two
// segments, a point in a part's own frame, a bound on a segment's distance to a solid cylinder, a
// placed part's projection on an axis, and the gap between two parts' projections on one part's own
// axes. Always inlined.
#include <limits>

#include "lane_parts.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::lanes {

/// select, or for a condition that holds in every lane alike (a bool) a plain choice.
template <class V, class M>
[[gnu::always_inline]] inline V choose(M condition, V yes, V no) {
  return select(condition, yes, no);
}
template <class V>
[[gnu::always_inline]] inline V choose(bool condition, V yes, V no) {
  return condition ? yes : no;
}

/// The point `c` in a placed part's own frame: about its centre `a`, along its axes (the rotation
/// transposed).
template <class V>
[[gnu::always_inline]] inline Point<V> inPartFrame(const ConvexPart& part, const Point<V>& c) {
  const Point<V> d = {c.x - part.a[0], c.y - part.a[1], c.z - part.a[2]};
  const double* m = part.axes;
  return {m[0] * d.x + m[3] * d.y + m[6] * d.z, m[1] * d.x + m[4] * d.y + m[7] * d.z,
          m[2] * d.x + m[5] * d.y + m[8] * d.z};
}

/// Distance between the segments p0-p1 and q0-q1 lane by lane, given 1 / their squared lengths
/// (where pointP / pointQ say a segment is a point, any value; masks, or bools when the same in
/// every lane): every branch of segmentDistance
/// (Ericson 5.1.9) computed and the right one selected. The same closest points up to rounding (a
/// few ulps; the callers' band is twelve orders of magnitude larger); with `Below` the distance is
/// a lower bound (sqrtBelow), else the correctly rounded root.
template <bool Below, class V, class M>
[[gnu::always_inline]] inline V segmentDistanceWith(const Point<V>& p0, const Point<V>& p1, const Point<V>& q0,
                                                    const Point<V>& q1, V inverseA, V inverseE, M pointP, M pointQ) {
  const V tiny = splat<V>(1e-24), one = splat<V>(1.0), zero = splat<V>(0.0);
  const Point<V> d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const V a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  const V denominator = a * e - b * b;
  const auto skew = denominator > tiny * (a + e);
  const V sFree = select(skew, clamp01((b * f - c * e) / select(skew, denominator, one)), zero);
  const V tFree = (b * sFree + f) * inverseE;
  const V sLow = clamp01(-c * inverseA), sHigh = clamp01((b - c) * inverseA);
  V s = select(tFree < 0.0, sLow, select(tFree > 1.0, sHigh, sFree));
  V t = clamp01(tFree);
  s = choose(pointQ, sLow, s);
  t = choose(pointQ, zero, t);
  t = choose(pointP, choose(pointQ, zero, clamp01(f * inverseE)), t);
  s = choose(pointP, zero, s);
  const V x = r.x + d1.x * s - d2.x * t, y = r.y + d1.y * s - d2.y * t, z = r.z + d1.z * s - d2.z * t;
  const V squared = x * x + y * y + z * z;
  return Below ? sqrtBelow(squared) : lanes::sqrt(squared);
}

/// segmentDistanceWith for any segments: their lengths from the points, lane by lane.
template <class V>
[[gnu::always_inline]] inline V segmentDistance(const Point<V>& p0, const Point<V>& p1, const Point<V>& q0,
                                                const Point<V>& q1) {
  const V tiny = splat<V>(1e-24), one = splat<V>(1.0);
  const Point<V> d1 = p1 - p0, d2 = q1 - q0;
  const V a = dot(d1, d1), e = dot(d2, d2);
  const auto pointP = a <= tiny, pointQ = e <= tiny;
  return segmentDistanceWith<false>(p0, p1, q0, q1, one / select(pointP, one, a), one / select(pointQ, one, e), pointP,
                                    pointQ);
}

/// segmentDistanceWith for segments whose lengths are known and the same in every lane (a part's),
/// given as 1 / their squared lengths (0 for a point): two divisions fewer; a lower bound.
template <class V>
[[gnu::always_inline]] inline V segmentDistance(const Point<V>& p0, const Point<V>& p1, const Point<V>& q0,
                                                const Point<V>& q1, double inverseA, double inverseE) {
  return segmentDistanceWith<true>(p0, p1, q0, q1, splat<V>(inverseA), splat<V>(inverseE), inverseA == 0.0,
                                   inverseE == 0.0);
}

/// 1 / the squared length of the segment a-b, 0 if it is (within 1e-12 m) a point.
inline double inverseSquaredLength(const double* a, const double* b) {
  const double x = b[0] - a[0], y = b[1] - a[1], z = b[2] - a[2], length2 = x * x + y * y + z * z;
  return length2 > 1e-24 ? 1.0 / length2 : 0.0;
}

/// A lower bound on the distance from the segment a-b to the solid cylinder (centre c, unit axis w,
/// radius R, half length h), lane by lane: with F the segment's least distance from the axis line
/// beyond R and G its least axial distance beyond h, every point of the segment is at least
/// sqrt(F^2 + G^2) from the cylinder (exact for a point).
template <class V>
[[gnu::always_inline]] inline V segmentCylinderDistance(const Point<V>& a, const Point<V>& b, const Point<V>& c,
                                                        const Point<V>& w, double R, double h) {
  const V zero = splat<V>(0.0);
  const Point<V> pa = a - c, pb = b - c;
  const V za = dot(pa, w), zb = dot(pb, w);
  const Point<V> qa = {pa.x - za * w.x, pa.y - za * w.y, pa.z - za * w.z};
  const Point<V> e = {pb.x - zb * w.x - qa.x, pb.y - zb * w.y - qa.y, pb.z - zb * w.z - qa.z};
  const V ee = dot(e, e);
  const V t = select(ee > 1e-24, clamp01(-dot(qa, e) / select(ee > 1e-24, ee, splat<V>(1.0))), zero);
  const Point<V> q = {qa.x + t * e.x, qa.y + t * e.y, qa.z + t * e.z};
  const V radial = max(sqrtBelow(dot(q, q)) - R, zero);
  const V axial = max(select(za * zb <= 0.0, zero, min(abs(za), abs(zb))) - h, zero);
  return sqrtBelow(radial * radial + axial * axial);
}

}  // namespace pmdplan::lanes

namespace pmdplan::fast {

using Kind = ConvexPart::Kind;

/// Centre and half width of a placed part of kind K (`part`, lane_parts.hpp) on the unit direction n.
template <Kind K, class V>
[[gnu::always_inline]] inline void project(const ConvexPart& shape, const double* part, const Point<V>& n, V& centre,
                                           V& halfWidth) {
  using lanes::abs;
  using lanes::dot;
  const Point<V> a = pointAt<V>(part);
  if constexpr (K == Kind::Capsule) {
    const V pa = dot(n, a), pb = dot(n, pointAt<V>(part + 3 * L));
    centre = 0.5 * (pa + pb), halfWidth = 0.5 * abs(pb - pa) + shape.radius;
  } else if constexpr (K == Kind::Box) {
    centre = dot(n, a);
    halfWidth = shape.half[0] * abs(dot(n, axisOf<V>(part, 0))) + shape.half[1] * abs(dot(n, axisOf<V>(part, 1))) +
                shape.half[2] * abs(dot(n, axisOf<V>(part, 2)));
  } else {
    centre = dot(n, a);
    const V w = abs(dot(n, axisOf<V>(part, 2)));
    halfWidth = shape.half[1] * w + shape.half[0] * lanes::sqrt(lanes::max(lanes::splat<V>(0.0), 1.0 - w * w));
  }
}

/// No gap proven yet: the start of the largest of the separating axes' gaps.
template <class V>
[[gnu::always_inline]] inline V noGap() {
  return lanes::splat<V>(-std::numeric_limits<double>::infinity());
}

/// `best` raised to the gaps between the parts' projections on the own part's axes (a box's face
/// normals, a cylinder's axis; Own is not a capsule): each a lower bound on their distance
/// (separating axes). On its own axes a part's half width is its half extent.
template <Kind Own, Kind Other, class V>
[[gnu::always_inline]] inline void separateOnAxesOf(const ConvexPart& own, const double* ownLanes,
                                                    const ConvexPart& other, const double* otherLanes, V& best) {
  static_assert(Own != Kind::Capsule, "a capsule has no axes of its own");
  const V ownCentre[3] = {pointAt<V>(ownLanes).x, pointAt<V>(ownLanes).y, pointAt<V>(ownLanes).z};
  for (int k = Own == Kind::Box ? 0 : 2; k < 3; ++k) {
    const Point<V> n = axisOf<V>(ownLanes, k);
    V centre, halfWidth;
    project<Other>(other, otherLanes, n, centre, halfWidth);
    const V ownHalf = lanes::splat<V>(Own == Kind::Box ? own.half[k] : own.half[1]);
    best = lanes::max(
        best, lanes::abs(n.x * ownCentre[0] + n.y * ownCentre[1] + n.z * ownCentre[2] - centre) - ownHalf - halfWidth);
  }
}

/// Whether every lane of `best` proves its pair apart: unless `tight` (every gap as tight as the
/// kernels get it), the kernels stop there (a looser bound, proof enough).
template <class V>
[[gnu::always_inline]] inline bool proven(V best, double band, bool tight) {
  return !tight && !lanes::any(best <= band);
}

/// `best` raised to the bound from the segment a-b (lane_parts.hpp's layout: a capsule's core, or
/// a box's or cylinder's outer capsule) of radius `radius` against the placed cylinder.
template <class V>
[[gnu::always_inline]] inline void separateFromCylinder(const double* ends, double radius, const ConvexPart& cylinder,
                                                        const double* cylinderLanes, V& best) {
  const V g = lanes::segmentCylinderDistance(pointAt<V>(ends), pointAt<V>(ends + 3 * L), pointAt<V>(cylinderLanes),
                                             axisOf<V>(cylinderLanes, 2), cylinder.half[0], cylinder.half[1]) -
              radius;
  best = lanes::max(best, g);
}

}  // namespace pmdplan::fast
