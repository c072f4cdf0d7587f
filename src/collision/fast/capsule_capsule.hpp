#pragma once
// The capsule–capsule kernel: two placed capsules' gap, their core segments' distance (a lower
// bound, lane_geometry.hpp) minus their radii, lane by lane over lane vectors of any width.
// Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

/// `inverseA`, `inverseB`: 1 / the cores' squared lengths (0 for a point), known at setup.
template <class V>
[[gnu::always_inline]] inline V capsuleCapsuleGap(const ConvexPart& capsuleA, const double* a, double inverseA,
                                                  const ConvexPart& capsuleB, const double* b, double inverseB) {
  return lanes::segmentDistance(pointAt<V>(a), pointAt<V>(a + 3 * L), pointAt<V>(b), pointAt<V>(b + 3 * L), inverseA,
                                inverseB) -
         (capsuleA.radius + capsuleB.radius);
}

}  // namespace pmdplan::fast
