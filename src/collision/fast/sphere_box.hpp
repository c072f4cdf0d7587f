#pragma once
// The sphere–box kernel: from spheres (the bounds of links, or of subtrees of links; centres c,
// radii r) to a box fixed in the world, lane by lane over lane vectors (lane_vector.hpp) of any
// width; a lower bound (sqrtBelow). The batch screen's broad phase against the obstacles. Always
// inlined.
#include "lane_vector.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V sphereBoxGap(const ConvexPart& box, const lanes::Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const lanes::Point<V> d = {c.x - box.a[0], c.y - box.a[1], c.z - box.a[2]};
  const double* m = box.axes;  // local coordinates: the rotation transposed
  const V u = m[0] * d.x + m[3] * d.y + m[6] * d.z, v = m[1] * d.x + m[4] * d.y + m[7] * d.z,
          w = m[2] * d.x + m[5] * d.y + m[8] * d.z;
  const V zero = lanes::splat<V>(0.0);
  const V ou = max(abs(u) - box.half[0], zero), ov = max(abs(v) - box.half[1], zero),
          ow = max(abs(w) - box.half[2], zero);
  return lanes::sqrtBelow(ou * ou + ov * ov + ow * ow) - r;
}

}  // namespace pmdplan::fast
