#pragma once
// The sphere–cylinder kernel: from spheres (the bounds of links, or of subtrees of links; centres
// c, radii r) to a cylinder fixed in the world, lane by lane over lane vectors (lane_vector.hpp)
// of any width; a lower bound (sqrtBelow). The batch screen's broad phase against the obstacles.
// Always inlined.
#include "lane_vector.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V sphereCylinderGap(const ConvexPart& cylinder, const lanes::Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const lanes::Point<V> d = {c.x - cylinder.a[0], c.y - cylinder.a[1], c.z - cylinder.a[2]};
  const double* m = cylinder.axes;  // local coordinates: the rotation transposed
  const V u = m[0] * d.x + m[3] * d.y + m[6] * d.z, v = m[1] * d.x + m[4] * d.y + m[7] * d.z,
          w = m[2] * d.x + m[5] * d.y + m[8] * d.z;
  const V zero = lanes::splat<V>(0.0);
  const V radial = max(lanes::sqrt(u * u + v * v) - cylinder.half[0], zero),
          axial = max(abs(w) - cylinder.half[1], zero);
  return lanes::sqrtBelow(radial * radial + axial * axial) - r;
}

}  // namespace pmdplan::fast
