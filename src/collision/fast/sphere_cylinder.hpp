#pragma once
// The sphere–cylinder kernel: from spheres (the bounds of links, or of subtrees of links; centres
// c, radii r) to a cylinder fixed in the world, lane by lane over lane vectors (lane_vector.hpp)
// of any width; a lower bound (sqrtBelow). The batch screen's broad phase against the obstacles.
// Always inlined.
#include "lane_geometry.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V sphereCylinderGap(const ConvexPart& cylinder, const lanes::Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const lanes::Point<V> local = lanes::inPartFrame(cylinder, c);
  const V zero = lanes::splat<V>(0.0);
  const V radial = max(lanes::sqrt(local.x * local.x + local.y * local.y) - cylinder.half[0], zero),
          axial = max(abs(local.z) - cylinder.half[1], zero);
  return lanes::sqrtBelow(radial * radial + axial * axial) - r;
}

}  // namespace pmdplan::fast
