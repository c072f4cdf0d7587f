// The batch screen (CheckerState::screenBatch): the geometric stages for kLanes configurations at
// once, on lane vectors (lane_vector.hpp) as wide as the running CPU's: all eight lanes in one AVX-512
// register, or two passes of four (AVX2), or four of two (SSE2). For every pair: the link bounds
// (a whole subtree of links against an obstacle first); where those meet, the parts' bounding
// spheres; where those meet, the parts themselves by the kernel of their two kinds (one header a
// pair: capsule_capsule.hpp, capsule_box.hpp, ..., cylinder_cylinder.hpp; chosen at setup). Only
// a lane whose pair none of these proves apart goes on, alone, to the one-configuration tests
// (linkPairContact / linkObstacleContact, then FCL).
#include <algorithm>
#include <limits>

#include "box_box.hpp"
#include "box_cylinder.hpp"
#include "capsule_box.hpp"
#include "capsule_capsule.hpp"
#include "capsule_cylinder.hpp"
#include "checker_state.hpp"
#include "cylinder_cylinder.hpp"
#include "lane_parts.hpp"
#include "sphere_box.hpp"
#include "sphere_capsule.hpp"
#include "sphere_cylinder.hpp"

namespace pmdplan::fast {
namespace {

constexpr int kValues = BatchedForwardKinematics::kPoseValues;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
using PairKind = CheckerState::PartPairKind;

/// The kernel of part pairs of kind K other than two capsules: a lower bound on the gap between
/// the placed parts a and b.
template <PairKind K, class V>
[[gnu::always_inline]] inline V solidPairGap(const ConvexPart& sa, const double* a, const ConvexPart& sb,
                                             const double* b, double band, bool tight) {
  if constexpr (K == PairKind::CapsuleBox)
    return capsuleBoxGap<V>(sa, a, sb, b);
  else if constexpr (K == PairKind::CapsuleCylinder)
    return capsuleCylinderGap<V>(sa, a, sb, b, band, tight);
  else if constexpr (K == PairKind::BoxBox)
    return boxBoxGap<V>(sa, a, sb, b, band, tight);
  else if constexpr (K == PairKind::BoxCylinder || K == PairKind::CylinderBox)
    return boxCylinderGap<K == PairKind::CylinderBox, V>(sa, a, sb, b, band, tight);
  else
    return cylinderCylinderGap<V>(sa, a, sb, b, band, tight);
}

/// The gaps of the part pairs of kind K whose bounding spheres meet (the first `count` of
/// partWork_'s list for K), by K's kernel, in lanes first .. first + width(V) - 1: into
/// partPairGaps_, over the bounding spheres' gap there (two capsules' replaces it; it is exact).
template <PairKind K, class V>
[[gnu::always_inline]] inline void partPairGaps(CheckerState& state, std::uint32_t count, int first, bool tight) {
  const std::uint32_t* work = state.partWork_.data() + state.partWorkBegin_[static_cast<int>(K)];
  const double* placed = state.partLanes_.data() + first;
  for (std::uint32_t w = 0; w < count; ++w) {
    const std::uint32_t k = work[w];
    const CheckerState::PartPair& pp = state.partPairs_[k];
    const ConvexPart &sa = state.partShapes_[pp.indexA], &sb = state.partShapes_[pp.indexB];
    const double* a = placed + static_cast<std::size_t>(pp.indexA) * kPartValues * L;
    const double* b = placed + static_cast<std::size_t>(pp.indexB) * kPartValues * L;
    double* g = state.partPairGaps_.data() + first + static_cast<std::size_t>(k) * L;
    if constexpr (K == PairKind::CapsuleCapsule)
      lanes::store(g, capsuleCapsuleGap<V>(sa, a, pp.inverseA, sb, b, pp.inverseB));
    else
      lanes::store(g, lanes::max(lanes::load<V>(g), solidPairGap<K, V>(sa, a, sb, b, state.band_, tight)));
  }
}

/// The sphere kernel for an obstacle of kind K.
template <ConvexPart::Kind K, class V>
[[gnu::always_inline]] inline V sphereGap(const ConvexPart& obstacle, const Point<V>& c, V r) {
  if constexpr (K == ConvexPart::Kind::Capsule)
    return sphereCapsuleGap(obstacle, c, r);
  else if constexpr (K == ConvexPart::Kind::Box)
    return sphereBoxGap(obstacle, c, r);
  else
    return sphereCylinderGap(obstacle, c, r);
}

}  // namespace

// Obstacle o (of kind K) against every moving link's bound, a whole subtree at a time where its
// sphere is clear of the obstacle: the sphere around a link's bound centre that holds its
// descendants' bounds (subtreeLanes_, radius grown by a relative 1e-12 against rounding).
template <ConvexPart::Kind K, class V>
[[gnu::always_inline]] inline void CheckerState::screenObstacleOf(std::size_t o, int first, bool tight) {
  using lanes::load;
  using lanes::store;
  const std::size_t selfCount = selfPairs_.size(), linkCount = geometricLinks_.size();
  const ConvexPart& obstacle = obstacles_[o].part;
  const double* subtree = subtreeLanes_.data() + first;
  double* obstacleGaps = pairLaneGaps_.data() + first + (selfCount + o * linkCount) * L;
  char* obstacleNear = pairNear_.data() + selfCount + o * linkCount;
  for (std::size_t i = 0; i < linkCount;) {
    const auto end = static_cast<std::size_t>(geometricSubtreeEnd_[i]);
    const Point<V> centre =
        pointAt<V>(boundLanes_.data() + static_cast<std::size_t>(geometricLinks_[i]) * 3 * L + first);
    if (!tight && end > i + 1) {
      const V whole = sphereGap<K>(obstacle, centre, load<V>(subtree + i * L) * (1.0 + 1e-12));
      if (!(lanes::lowest(whole) <= band_)) {
        for (; i < end; ++i) store(obstacleGaps + i * L, whole), obstacleNear[i] = 0;
        continue;
      }
    }
    const V gap = sphereGap<K>(obstacle, centre, lanes::splat<V>(geometricBoundR_[i]));
    store(obstacleGaps + i * L, gap);
    obstacleNear[i] = lanes::lowest(gap) <= band_;
    ++i;
  }
}

// Lanes first .. first + width(V) - 1, in passes that keep the data-dependent branches out of the
// long loops: (1) every pair's bounds; (2) for the pairs whose bounds meet in some lane, their links
// placed, every part pair's bounding spheres, then where those meet the kernel of the pair's kinds
// (one loop per kind of pair, PartPairKind), then each pair's smallest part gap; (3) the safe
// value. Leaves each pair's gap (a lower bound; +inf in a lane left open) in pairLaneGaps_, the
// smallest gap * share in laneSafe_, and in laneScalar_ the pairs each lane must test alone. Lanes
// from `count` on repeat the last configuration: they are computed, never reported.
template <class V>
[[gnu::always_inline]] inline void CheckerState::screenLanesOf(const double* poses, int count, int first, bool tight) {
  using lanes::load;
  using lanes::store;
  constexpr int W = lanes::widthOf<V>;
  const std::size_t selfCount = selfPairs_.size(), linkCount = geometricLinks_.size(), pairs = pairCount();
  lanes::MaskOf<V> active;
  for (int l = 0; l < W; ++l) active[l] = first + l < count ? -1 : 0;
  poses += first;
  double* gaps = pairLaneGaps_.data() + first;
  double* partGaps = partPairGaps_.data() + first;
  const auto part = [&](std::uint32_t index) {
    return partLanes_.data() + static_cast<std::size_t>(index) * kPartValues * L + first;
  };
  const auto bound = [&](int link) {
    return pointAt<V>(boundLanes_.data() + static_cast<std::size_t>(link) * 3 * L + first);
  };
  const auto place = [&](int link) {
    const auto l = static_cast<std::size_t>(link);
    if (partLanesPlaced_[l]) return;
    partLanesPlaced_[l] = 1;
    const double* m = poses + l * kValues * L;
    const auto& parts = links_[l].parts;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const ConvexPart& shape = parts[i];
      double* out = part(static_cast<std::uint32_t>(partOffset_[l]) + static_cast<std::uint32_t>(i));
      storePoint(out, transformed<V>(m, shape.a));
      storePoint(out + kPartBound * L, transformed<V>(m, shape.boundCentre));
      if (shape.kind == ConvexPart::Kind::Capsule) {
        storePoint(out + 3 * L, transformed<V>(m, shape.b));
        continue;
      }
      storePoint(out + kPartOuter * L, transformed<V>(m, shape.outerA));
      storePoint(out + (kPartOuter + 3) * L, transformed<V>(m, shape.outerB));
      for (int r = 0; r < 3; ++r)  // world axes: the link's rotation times the part's
        for (int c = 0; c < 3; ++c)
          store(out + (kPartAxes + r * 3 + c) * L, load<V>(m + (r * 3) * L) * shape.axes[c] +
                                                       load<V>(m + (r * 3 + 1) * L) * shape.axes[3 + c] +
                                                       load<V>(m + (r * 3 + 2) * L) * shape.axes[6 + c]);
    }
  };

  // (1) Bounds.
  std::fill(partLanesPlaced_.begin(), partLanesPlaced_.end(), 0);
  for (int l : boundLinks_)
    storePoint(boundLanes_.data() + static_cast<std::size_t>(l) * 3 * L + first,
               transformed<V>(poses + static_cast<std::size_t>(l) * kValues * L,
                              links_[static_cast<std::size_t>(l)].boundCentre));
  for (std::size_t p = 0; p < selfCount; ++p) {
    const Point<V> d = bound(pairA_[p]) - bound(pairB_[p]);
    const V gap = lanes::sqrtBelow(lanes::dot(d, d)) - pairRadiusSum_[p];
    store(gaps + p * L, gap);
    pairNear_[p] = lanes::lowest(gap) <= band_;
  }
  // Against the obstacles: each obstacle's subtree radii first.
  double* subtree = subtreeLanes_.data() + first;
  for (std::size_t i = 0; i < linkCount; ++i) store(subtree + i * L, lanes::splat<V>(geometricBoundR_[i]));
  for (std::size_t i = linkCount; i-- > 0;) {
    const int parent = geometricParent_[i];
    if (parent < 0) continue;
    const Point<V> d = bound(geometricLinks_[i]) - bound(geometricLinks_[static_cast<std::size_t>(parent)]);
    double* r = subtree + static_cast<std::size_t>(parent) * L;
    store(r, lanes::max(load<V>(r), lanes::sqrt(lanes::dot(d, d)) + load<V>(subtree + i * L)));
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o) switch (obstacles_[o].part.kind) {
      case ConvexPart::Kind::Capsule:
        screenObstacleOf<ConvexPart::Kind::Capsule, V>(o, first, tight);
        break;
      case ConvexPart::Kind::Box:
        screenObstacleOf<ConvexPart::Kind::Box, V>(o, first, tight);
        break;
      case ConvexPart::Kind::Cylinder:
        screenObstacleOf<ConvexPart::Kind::Cylinder, V>(o, first, tight);
        break;
      case ConvexPart::Kind::Triangle:
        break;  // only the exact checker's mesh route holds triangles
    }

  // (2) Parts.
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!pairNear_[pair]) continue;
    if (pair < selfCount) {
      place(pairA_[pair]);
      place(pairB_[pair]);
    } else {
      place(geometricLinks_[(pair - selfCount) % linkCount]);
    }
  }
  std::uint32_t counts[kPartPairKinds] = {};  // of partWork_'s lists
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!pairNear_[pair]) continue;
    for (std::uint32_t k = pairPartsBegin_[pair]; k < pairPartsBegin_[pair + 1]; ++k) {
      const PartPair& pp = partPairs_[k];
      const Point<V> d = pointAt<V>(part(pp.indexA) + kPartBound * L) - pointAt<V>(part(pp.indexB) + kPartBound * L);
      const V spheres = lanes::sqrtBelow(lanes::dot(d, d)) -
                        (partShapes_[pp.indexA].boundRadius + partShapes_[pp.indexB].boundRadius);
      store(partGaps + static_cast<std::size_t>(k) * L, spheres);
      const bool meet = tight || lanes::lowest(spheres) <= band_;  // tight: every part pair measured
      const auto kind = static_cast<int>(pp.kind);
      partWork_[partWorkBegin_[kind] + counts[kind]] = k;
      counts[kind] += meet;
    }
  }
  const auto at = [](PairKind kind) { return static_cast<int>(kind); };
  partPairGaps<PairKind::CapsuleCapsule, V>(*this, counts[at(PairKind::CapsuleCapsule)], first, tight);
  partPairGaps<PairKind::CapsuleBox, V>(*this, counts[at(PairKind::CapsuleBox)], first, tight);
  partPairGaps<PairKind::CapsuleCylinder, V>(*this, counts[at(PairKind::CapsuleCylinder)], first, tight);
  partPairGaps<PairKind::BoxBox, V>(*this, counts[at(PairKind::BoxBox)], first, tight);
  partPairGaps<PairKind::BoxCylinder, V>(*this, counts[at(PairKind::BoxCylinder)], first, tight);
  partPairGaps<PairKind::CylinderBox, V>(*this, counts[at(PairKind::CylinderBox)], first, tight);
  partPairGaps<PairKind::CylinderCylinder, V>(*this, counts[at(PairKind::CylinderCylinder)], first, tight);
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!pairNear_[pair]) continue;
    V partsGap = lanes::splat<V>(kInfinity);
    for (std::uint32_t k = pairPartsBegin_[pair]; k < pairPartsBegin_[pair + 1]; ++k)
      partsGap = lanes::min(partsGap, load<V>(partGaps + static_cast<std::size_t>(k) * L));
    const V gap = load<V>(gaps + pair * L);
    const auto near = gap <= band_, alone = (partsGap <= band_) & near & active;
    store(gaps + pair * L, lanes::select<V>(alone, lanes::splat<V>(kInfinity), lanes::select<V>(near, partsGap, gap)));
    if (lanes::any(alone))
      for (unsigned b = lanes::bits(alone); b; b &= b - 1) laneScalar_[first + __builtin_ctz(b)].push_back(pair);
  }

  // (3) The safe value.
  V safe = lanes::splat<V>(kInfinity);
  for (std::size_t p = 0; p < selfCount; ++p) safe = lanes::min(safe, load<V>(gaps + p * L) * pairShare_[p]);
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    for (std::size_t i = 0; i < linkCount; ++i)
      safe = lanes::min(safe, load<V>(gaps + (selfCount + o * linkCount + i) * L) * linkShare_[i]);
  store(laneSafe_ + first, safe);
}

namespace {

// screenLanes at each SIMD level: the lane-vector stage built for that instruction set.
[[gnu::target("avx512f")]] void screenAvx512(CheckerState& state, const double* poses, int count, bool tight) {
  state.screenLanesOf<lanes::Vec<8>>(poses, count, 0, tight);
}
[[gnu::target("avx2")]] void screenAvx2(CheckerState& state, const double* poses, int count, bool tight) {
  for (int first = 0; first < count; first += 4) state.screenLanesOf<lanes::Vec<4>>(poses, count, first, tight);
}
void screenSse2(CheckerState& state, const double* poses, int count, bool tight) {
  for (int first = 0; first < count; first += 2) state.screenLanesOf<lanes::Vec<2>>(poses, count, first, tight);
}

}  // namespace

void CheckerState::screenLanes(const double* poses, int count, bool tight) {
  switch (simdLevel_) {
    case SimdLevel::avx512:
      return screenAvx512(*this, poses, count, tight);
    case SimdLevel::avx2:
      return screenAvx2(*this, poses, count, tight);
    case SimdLevel::sse2:
      break;
  }
  screenSse2(*this, poses, count, tight);
}

int CheckerState::screenBatch(const Configuration* const* configurations, int count, const double* poses, bool* valid,
                              double* safe, double* pairGaps, const bool* stopAt) {
  const std::size_t selfCount = selfPairs_.size(), linkCount = geometricLinks_.size(), pairs = pairCount();
  if (!(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    for (int lane = 0; lane < count; ++lane) valid[lane] = false, safe[lane] = 0.0, ++statistics_.provenColliding;
    return stopAt && !*stopAt ? 0 : count;
  }
  for (int lane = 0; lane < count; ++lane) laneScalar_[lane].clear();
  screenLanes(poses, count, pairGaps != nullptr);

  // Lane by lane: the pairs the lane vectors left open, FCL for those within the band, the verdict.
  for (int lane = 0; lane < count; ++lane) {
    beginLane(poses, L, lane);
    uncertain_.clear();
    bool overlapping = false;
    double laneSafe = laneSafe_[lane];
    for (const std::size_t pair : laneScalar_[lane]) {
      const bool self = pair < selfCount;
      const std::size_t i = self ? 0 : (pair - selfCount) % linkCount, o = self ? 0 : (pair - selfCount) / linkCount;
      const int a = self ? pairA_[pair] : geometricLinks_[i], b = self ? pairB_[pair] : static_cast<int>(o);
      if (self && !boundPlaced_[static_cast<std::size_t>(b)]) placeBound(b);  // linkPairContact reads b's bound
      double gap;
      const Outcome outcome = self ? linkPairContact(a, b, gap) : linkObstacleContact(a, o, gap);
      if (outcome == Outcome::Overlapping) {
        overlapping = true;
        break;
      }
      if (outcome != Outcome::Apart) {
        uncertain_.push_back(Flag{self, a, b, outcome});
        gap = 0.0;
      }
      pairLaneGaps_[pair * L + static_cast<std::size_t>(lane)] = gap;
      laneSafe = std::min(laneSafe, gap * (self ? pairShare_[pair] : linkShare_[i]));
    }
    safe[lane] = 0.0;
    if (overlapping) {
      ++statistics_.provenColliding;
      valid[lane] = false;
      if (stopAt && !*stopAt) return lane;
      continue;
    }
    if (pairGaps)
      for (std::size_t pair = 0; pair < pairs; ++pair)
        pairGaps[static_cast<std::size_t>(lane) * pairs + pair] =
            pairLaneGaps_[pair * L + static_cast<std::size_t>(lane)];
    if (uncertain_.empty()) {
      ++statistics_.provenFree;
      valid[lane] = true;
      safe[lane] = laneSafe;
    } else {
      valid[lane] = confirmUncertain(*configurations[lane]);
    }
    if (stopAt && valid[lane] == *stopAt) return lane;
  }
  return count;
}

}  // namespace pmdplan::fast
