#pragma once
// The cylinder–cylinder kernel: a lower bound on the gap between two placed cylinders, lane by
// lane over lane vectors of any width: their projections on the first's axis, then where lanes
// are left unproven (or when `tight`) on the second's, then each one's outer capsule against the
// other solid cylinder (lane_geometry.hpp). Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V cylinderCylinderGap(const ConvexPart& first, const double* a, const ConvexPart& second,
                                                    const double* b, double band, bool tight) {
  V best = noGap<V>();
  separateOnAxesOf<Kind::Cylinder, Kind::Cylinder>(first, a, second, b, best);
  if (proven(best, band, tight)) return best;
  separateOnAxesOf<Kind::Cylinder, Kind::Cylinder>(second, b, first, a, best);
  if (proven(best, band, tight)) return best;
  separateFromCylinder(a + kPartOuter * L, first.outerRadius, second, b, best);
  if (proven(best, band, tight)) return best;
  separateFromCylinder(b + kPartOuter * L, second.outerRadius, first, a, best);
  return best;
}

}  // namespace pmdplan::fast
