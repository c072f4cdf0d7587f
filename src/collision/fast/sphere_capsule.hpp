#pragma once
// The sphere–capsule kernel: from spheres (the bounds of links, or of subtrees of links; centres
// c, radii r) to a capsule fixed in the world, lane by lane over lane vectors (lane_vector.hpp) of
// any width; a lower bound (sqrtBelow). The batch screen's broad phase against the obstacles.
// Always inlined.
#include "lane_vector.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V sphereCapsuleGap(const ConvexPart& capsule, const lanes::Point<V>& c, V r) {
  const lanes::Point<V> d = {c.x - capsule.a[0], c.y - capsule.a[1], c.z - capsule.a[2]};
  const double ex = capsule.b[0] - capsule.a[0], ey = capsule.b[1] - capsule.a[1], ez = capsule.b[2] - capsule.a[2];
  const double length2 = ex * ex + ey * ey + ez * ez, inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
  const V t = lanes::clamp01((d.x * ex + d.y * ey + d.z * ez) * inverse);
  const lanes::Point<V> q = {d.x - t * ex, d.y - t * ey, d.z - t * ez};
  return lanes::sqrtBelow(lanes::dot(q, q)) - (capsule.radius + r);
}

}  // namespace pmdplan::fast
