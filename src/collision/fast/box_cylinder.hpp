#pragma once
// The box–cylinder kernel: a lower bound on the gap between a placed box and a placed cylinder,
// lane by lane over lane vectors of any width: their projections on the box's face normals and the
// cylinder's axis (the first part's axes first, the other's only where those leave a lane unproven
// or when `tight`), then the box's outer capsule against the solid cylinder (lane_geometry.hpp).
// Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

/// `CylinderFirst`: the pair has the cylinder first, so its axis is tried first.
template <bool CylinderFirst, class V>
[[gnu::always_inline]] inline V boxCylinderGap(const ConvexPart& box, const double* b, const ConvexPart& cylinder,
                                               const double* y, double band, bool tight) {
  V best = noGap<V>();
  if constexpr (CylinderFirst) {
    separateOnAxesOf<Kind::Cylinder, Kind::Box>(cylinder, y, box, b, best);
    if (proven(best, band, tight)) return best;
    separateOnAxesOf<Kind::Box, Kind::Cylinder>(box, b, cylinder, y, best);
  } else {
    separateOnAxesOf<Kind::Box, Kind::Cylinder>(box, b, cylinder, y, best);
    if (proven(best, band, tight)) return best;
    separateOnAxesOf<Kind::Cylinder, Kind::Box>(cylinder, y, box, b, best);
  }
  if (proven(best, band, tight)) return best;
  separateFromCylinder(b + kPartOuter * L, box.outerRadius, cylinder, y, best);
  return best;
}

}  // namespace pmdplan::fast
