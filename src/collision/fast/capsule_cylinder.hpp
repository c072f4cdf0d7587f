#pragma once
// The capsule–cylinder kernel: a lower bound on the gap between a placed capsule and a placed
// cylinder, lane by lane over lane vectors of any width: their projections on the cylinder's axis,
// then where that leaves a lane unproven the capsule's core against the solid cylinder
// (lane_geometry.hpp). Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V capsuleCylinderGap(const ConvexPart& capsule, const double* c,
                                                   const ConvexPart& cylinder, const double* y, double band,
                                                   bool tight) {
  V best = noGap<V>();
  separateOnAxesOf<Kind::Cylinder, Kind::Capsule>(cylinder, y, capsule, c, best);
  if (proven(best, band, tight)) return best;
  separateFromCylinder(c, capsule.radius, cylinder, y, best);
  return best;
}

}  // namespace pmdplan::fast
