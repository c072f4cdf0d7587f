#pragma once
// The sphere–obstacle kernel: from bounding spheres (of a link, or of a subtree of links) to a part
// fixed in the world (capsule, box or cylinder), lane by lane over lane vectors of any width; the
// batch screen's broad phase against the obstacles. Always inlined.
#include "lane_vector.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

using lanes::Point;

/// sphereGap lane by lane: from spheres (centres c, radius r) to a part fixed in the world; a lower
/// bound (sqrtBelow).
template <class V>
[[gnu::always_inline]] inline V obstacleSphereGap(const ConvexPart& part, const Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const Point<V> d = {c.x - part.a[0], c.y - part.a[1], c.z - part.a[2]};
  if (part.kind == ConvexPart::Kind::Capsule) {
    const double ex = part.b[0] - part.a[0], ey = part.b[1] - part.a[1], ez = part.b[2] - part.a[2];
    const double length2 = ex * ex + ey * ey + ez * ez, inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
    const V t = lanes::clamp01((d.x * ex + d.y * ey + d.z * ez) * inverse);
    const Point<V> q = {d.x - t * ex, d.y - t * ey, d.z - t * ez};
    return lanes::sqrtBelow(lanes::dot(q, q)) - (part.radius + r);
  }
  const double* m = part.axes;  // local coordinates: the rotation transposed
  const V u = m[0] * d.x + m[3] * d.y + m[6] * d.z, v = m[1] * d.x + m[4] * d.y + m[7] * d.z,
          w = m[2] * d.x + m[5] * d.y + m[8] * d.z;
  const V zero = lanes::splat<V>(0.0);
  if (part.kind == ConvexPart::Kind::Box) {
    const V ou = max(abs(u) - part.half[0], zero), ov = max(abs(v) - part.half[1], zero),
            ow = max(abs(w) - part.half[2], zero);
    return lanes::sqrtBelow(ou * ou + ov * ov + ow * ow) - r;
  }
  const V radial = max(lanes::sqrt(u * u + v * v) - part.half[0], zero), axial = max(abs(w) - part.half[1], zero);
  return lanes::sqrtBelow(radial * radial + axial * axial) - r;
}

}  // namespace pmdplan::fast
