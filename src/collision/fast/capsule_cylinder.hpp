#pragma once
// The capsule–cylinder kernel: a lower bound on the distance from a segment (a capsule's core, or
// the outer capsule of a box or cylinder) to a solid cylinder, lane by lane over lane vectors
// (lane_vector.hpp) of any width. Always inlined into the kernels that use it (solid_gap.hpp).
#include "lane_vector.hpp"

namespace pmdplan::lanes {

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
