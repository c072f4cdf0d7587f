// The batch screen (CheckerState::screenBatch): the geometric stages for kLanes configurations at once, on
// lane vectors (lane_vector.hpp) as wide as the running CPU's: all eight lanes in one AVX-512
// register, or two passes of four (AVX2), or four of two (SSE2). For every pair: the link bounds
// (a whole subtree of links against an obstacle first); where those meet, the parts' bounding
// spheres; where those meet, the parts themselves — capsules by their exact distance, boxes and
// cylinders by separating axes (face normals and cylinder axes) and a segment-cylinder bound. Only
// a lane whose pair none of these proves apart goes on, alone, to the one-configuration tests
// (linkPairContact / linkObstacleContact, then FCL).
#include <algorithm>
#include <limits>

#include "capsule_capsule.hpp"
#include "checker_state.hpp"
#include "lane_parts.hpp"
#include "solid_gap.hpp"
#include "sphere_obstacle.hpp"

namespace pmdplan::fast {
namespace {

constexpr int kValues = BatchedForwardKinematics::kPoseValues;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

// Lanes first .. first + width(V) - 1, in passes that keep the data-dependent branches out of the
// long loops: (1) every pair's bounds; (2) for the pairs whose bounds meet in some lane, their links
// placed, every part pair's bounding spheres, then where those meet the exact capsule distance or
// the separating axes (each kind in one loop), then each pair's smallest part gap; (3) the safe
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
  // Against the obstacles, a whole subtree at a time where its sphere is clear of the obstacle: the
  // sphere around a link's bound centre that holds its descendants' bounds (radius grown by a
  // relative 1e-12 against rounding).
  double* subtree = subtreeLanes_.data() + first;
  for (std::size_t i = 0; i < linkCount; ++i) store(subtree + i * L, lanes::splat<V>(geometricBoundR_[i]));
  for (std::size_t i = linkCount; i-- > 0;) {
    const int parent = geometricParent_[i];
    if (parent < 0) continue;
    const Point<V> d = bound(geometricLinks_[i]) - bound(geometricLinks_[static_cast<std::size_t>(parent)]);
    double* r = subtree + static_cast<std::size_t>(parent) * L;
    store(r, lanes::max(load<V>(r), lanes::sqrt(lanes::dot(d, d)) + load<V>(subtree + i * L)));
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const ConvexPart& obstacle = obstacles_[o].part;
    double* obstacleGaps = gaps + (selfCount + o * linkCount) * L;
    char* obstacleNear = pairNear_.data() + selfCount + o * linkCount;
    for (std::size_t i = 0; i < linkCount;) {
      const auto end = static_cast<std::size_t>(geometricSubtreeEnd_[i]);
      const Point<V> centre = bound(geometricLinks_[i]);
      if (!tight && end > i + 1) {
        const V whole = obstacleSphereGap(obstacle, centre, load<V>(subtree + i * L) * (1.0 + 1e-12));
        if (!(lanes::lowest(whole) <= band_)) {
          for (; i < end; ++i) store(obstacleGaps + i * L, whole), obstacleNear[i] = 0;
          continue;
        }
      }
      const V gap = obstacleSphereGap(obstacle, centre, lanes::splat<V>(geometricBoundR_[i]));
      store(obstacleGaps + i * L, gap);
      obstacleNear[i] = lanes::lowest(gap) <= band_;
      ++i;
    }
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
  std::size_t capsules = 0, faces = 0;
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!pairNear_[pair]) continue;
    for (std::uint32_t k = pairPartsBegin_[pair]; k < pairPartsBegin_[pair + 1]; ++k) {
      const PartPair& pp = partPairs_[k];
      const Point<V> d = pointAt<V>(part(pp.indexA) + kPartBound * L) - pointAt<V>(part(pp.indexB) + kPartBound * L);
      const V spheres = lanes::sqrtBelow(lanes::dot(d, d)) -
                        (partShapes_[pp.indexA].boundRadius + partShapes_[pp.indexB].boundRadius);
      store(partGaps + static_cast<std::size_t>(k) * L, spheres);
      const bool meet = tight || lanes::lowest(spheres) <= band_;  // tight: every part pair measured
      (pp.capsules ? capsuleWork_[capsules] : faceWork_[faces]) = k;
      (pp.capsules ? capsules : faces) += meet;
    }
  }
  for (std::size_t w = 0; w < capsules; ++w) {
    const std::uint32_t k = capsuleWork_[w];
    const PartPair& pp = partPairs_[k];
    const double *a = part(pp.indexA), *b = part(pp.indexB);
    store(partGaps + static_cast<std::size_t>(k) * L,
          lanes::segmentDistance(pointAt<V>(a), pointAt<V>(a + 3 * L), pointAt<V>(b), pointAt<V>(b + 3 * L),
                                 pp.inverseA, pp.inverseB) -
              (partShapes_[pp.indexA].radius + partShapes_[pp.indexB].radius));
  }
  for (std::size_t w = 0; w < faces; ++w) {
    const std::uint32_t k = faceWork_[w];
    const PartPair& pp = partPairs_[k];
    double* g = partGaps + static_cast<std::size_t>(k) * L;
    store(g, lanes::max(load<V>(g), solidGap<V>(partShapes_[pp.indexA], part(pp.indexA), partShapes_[pp.indexB],
                                                part(pp.indexB), band_, tight)));
  }
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

void CheckerState::screenBatch(const Configuration* const* configurations, int count, const double* poses, bool* valid,
                               double* safe, double* pairGaps) {
  const std::size_t selfCount = selfPairs_.size(), linkCount = geometricLinks_.size(), pairs = pairCount();
  if (!(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    for (int lane = 0; lane < count; ++lane) valid[lane] = false, safe[lane] = 0.0, ++statistics_.provenColliding;
    return;
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
  }
}

}  // namespace pmdplan::fast
