#pragma once
// The separating-axes kernel, for every pair of parts with a box or a cylinder (box–box,
// capsule–box, box–cylinder, capsule–cylinder, cylinder–cylinder): the parts' projections on the
// boxes' face normals and the cylinders' axes, lane by lane over lane vectors of any width; the
// largest gap between them is a lower bound on the parts' distance. Always inlined.
#include <limits>

#include "lane_parts.hpp"
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan::fast {

/// Centre and half width of a placed part's projection on the unit direction n.
template <class V>
[[gnu::always_inline]] inline void project(const ConvexPart& shape, const double* part, const Point<V>& n, V& centre,
                                           V& halfWidth) {
  using lanes::abs;
  using lanes::dot;
  const Point<V> a = pointAt<V>(part);
  if (shape.kind == ConvexPart::Kind::Capsule) {
    const V pa = dot(n, a), pb = dot(n, pointAt<V>(part + 3 * L));
    centre = 0.5 * (pa + pb), halfWidth = 0.5 * abs(pb - pa) + shape.radius;
    return;
  }
  centre = dot(n, a);
  if (shape.kind == ConvexPart::Kind::Box) {
    halfWidth = shape.half[0] * abs(dot(n, axisOf<V>(part, 0))) + shape.half[1] * abs(dot(n, axisOf<V>(part, 1))) +
                shape.half[2] * abs(dot(n, axisOf<V>(part, 2)));
  } else {
    const V w = abs(dot(n, axisOf<V>(part, 2)));
    halfWidth = shape.half[1] * w + shape.half[0] * lanes::sqrt(lanes::max(lanes::splat<V>(0.0), 1.0 - w * w));
  }
}

/// The largest gap between the parts' projections on the face normals of their boxes and the axes
/// of their cylinders: a lower bound on their distance (separating axes, as faceSeparation). On
/// its own axes a part's half width is its half extent. Unless `tight`, the second part's axes are
/// tried only if the first part's leave some lane unproven (a looser bound, proof enough).
template <class V>
[[gnu::always_inline]] inline V faceSeparation(const ConvexPart& shapeA, const double* a, const ConvexPart& shapeB,
                                               const double* b, double band, bool tight) {
  V best = lanes::splat<V>(-std::numeric_limits<double>::infinity());
  const auto alongAxesOf = [&](const ConvexPart& own, const double* ownLanes, const ConvexPart& other,
                               const double* otherLanes) {
    if (own.kind == ConvexPart::Kind::Capsule) return;
    const V ownCentre[3] = {pointAt<V>(ownLanes).x, pointAt<V>(ownLanes).y, pointAt<V>(ownLanes).z};
    for (int k = own.kind == ConvexPart::Kind::Box ? 0 : 2; k < 3; ++k) {
      const Point<V> n = axisOf<V>(ownLanes, k);
      V centre, halfWidth;
      project(other, otherLanes, n, centre, halfWidth);
      const V ownHalf = lanes::splat<V>(own.kind == ConvexPart::Kind::Box ? own.half[k] : own.half[1]);
      best = lanes::max(best, lanes::abs(n.x * ownCentre[0] + n.y * ownCentre[1] + n.z * ownCentre[2] - centre) -
                                  ownHalf - halfWidth);
    }
  };
  alongAxesOf(shapeA, a, shapeB, b);
  if (!tight && shapeA.kind != ConvexPart::Kind::Capsule && !lanes::any(best <= band)) return best;
  alongAxesOf(shapeB, b, shapeA, a);
  return best;
}

}  // namespace pmdplan::fast
