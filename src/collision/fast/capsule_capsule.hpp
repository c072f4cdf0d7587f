#pragma once
// The capsule–capsule kernel: the distance between two capsules' core segments, lane by lane over
// lane vectors (lane_vector.hpp) of any width; the capsules' gap is that minus their radii. Always
// inlined into the kernels that use it (the batch screen, convex_distance.cpp's segmentDistances).
#include "lane_vector.hpp"

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

}  // namespace pmdplan::lanes
