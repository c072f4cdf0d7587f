#pragma once
// The box–box kernel: a lower bound on the gap between two placed boxes, the largest gap between
// their projections on the first box's face normals, then where those leave a lane unproven (or
// when `tight`) on the second's (lane_geometry.hpp); lane by lane over lane vectors of any width.
// Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V boxBoxGap(const ConvexPart& first, const double* a, const ConvexPart& second,
                                          const double* b, double band, bool tight) {
  V best = noGap<V>();
  separateOnAxesOf<Kind::Box, Kind::Box>(first, a, second, b, best);
  if (proven(best, band, tight)) return best;
  separateOnAxesOf<Kind::Box, Kind::Box>(second, b, first, a, best);
  return best;
}

}  // namespace pmdplan::fast
