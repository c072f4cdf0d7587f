#pragma once
// The kernel for every pair of parts that are not two capsules (those: capsule_capsule.hpp): the
// separating axes (separating_axes.hpp), tightened where a part is a cylinder by the other's core
// or outer capsule against it (capsule_cylinder.hpp). Lane vectors of any width; always inlined.
#include "capsule_cylinder.hpp"
#include "separating_axes.hpp"

namespace pmdplan::fast {

/// A lower bound on the gap between two placed parts that are not both capsules: separating axes,
/// and where those leave a lane unproven and a part is a cylinder, the other part's core (a
/// capsule's) or outer capsule against that cylinder.
template <class V>
[[gnu::always_inline]] inline V solidGap(const ConvexPart& shapeA, const double* a, const ConvexPart& shapeB,
                                         const double* b, double band, bool tight) {
  V best = faceSeparation<V>(shapeA, a, shapeB, b, band, tight);
  const auto againstCylinder = [&](const ConvexPart& other, const double* otherLanes, const ConvexPart& cylinder,
                                   const double* cylinderLanes) {
    if (cylinder.kind != ConvexPart::Kind::Cylinder || (!tight && !lanes::any(best <= band))) return;
    const bool capsule = other.kind == ConvexPart::Kind::Capsule;
    const double* ends = capsule ? otherLanes : otherLanes + kPartOuter * L;
    const V g = lanes::segmentCylinderDistance(pointAt<V>(ends), pointAt<V>(ends + 3 * L), pointAt<V>(cylinderLanes),
                                               axisOf<V>(cylinderLanes, 2), cylinder.half[0], cylinder.half[1]) -
                (capsule ? other.radius : other.outerRadius);
    best = lanes::max(best, g);
  };
  againstCylinder(shapeA, a, shapeB, b);
  againstCylinder(shapeB, b, shapeA, a);
  return best;
}

}  // namespace pmdplan::fast
