#pragma once
// The sphere–box kernel: from spheres (the bounds of links, or of subtrees of links; centres c,
// radii r) to a box fixed in the world, lane by lane over lane vectors (lane_vector.hpp) of any
// width; a lower bound (sqrtBelow). The batch screen's broad phase against the obstacles. Always
// inlined.
#include "lane_geometry.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V sphereBoxGap(const ConvexPart& box, const lanes::Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const lanes::Point<V> local = lanes::inPartFrame(box, c);
  const V zero = lanes::splat<V>(0.0);
  const V ou = max(abs(local.x) - box.half[0], zero), ov = max(abs(local.y) - box.half[1], zero),
          ow = max(abs(local.z) - box.half[2], zero);
  return lanes::sqrtBelow(ou * ou + ov * ov + ow * ow) - r;
}

}  // namespace pmdplan::fast
