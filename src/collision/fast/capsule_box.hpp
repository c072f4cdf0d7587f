#pragma once
// The capsule–box kernel: a lower bound on the gap between a placed capsule and a placed box, the
// largest gap between their projections on the box's face normals (lane_geometry.hpp), lane by
// lane over lane vectors of any width. Always inlined into the batch screen.
#include "lane_geometry.hpp"

namespace pmdplan::fast {

template <class V>
[[gnu::always_inline]] inline V capsuleBoxGap(const ConvexPart& capsule, const double* c, const ConvexPart& box,
                                              const double* b) {
  V best = noGap<V>();
  separateOnAxesOf<Kind::Box, Kind::Capsule>(box, b, capsule, c, best);
  return best;
}

}  // namespace pmdplan::fast
