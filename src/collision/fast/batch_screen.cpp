// The batch screen (batch_screen.hpp): the geometric stages for kLanes configurations at
// once, on lane vectors (lane_vector.hpp) as wide as the running CPU's: all eight lanes in one AVX-512
// register, or two passes of four (AVX2), or four of two (SSE2). For every pair: the link bounds
// (a whole subtree of links against an obstacle first); where those meet, the parts' bounding
// spheres; where those meet, the parts themselves by the kernel of their two kinds (one header a
// pair: capsule_capsule.hpp, capsule_box.hpp, ..., cylinder_cylinder.hpp; chosen at setup). Only
// a lane whose pair none of these proves apart goes on, alone, to the one-configuration tests
// (linkPairContact / linkObstacleContact, then FCL).
#include "batch_screen.hpp"

#include <algorithm>
#include <limits>

#include "box_box.hpp"
#include "box_cylinder.hpp"
#include "capsule_box.hpp"
#include "capsule_capsule.hpp"
#include "capsule_cylinder.hpp"
#include "checker_model.hpp"
#include "checker_scratch.hpp"
#include "cylinder_cylinder.hpp"
#include "lane_parts.hpp"
#include "narrow_phase.hpp"
#include "sphere_box.hpp"
#include "sphere_capsule.hpp"
#include "sphere_cylinder.hpp"

namespace pmdplan::fast {
namespace {

constexpr int kBatchValues = BatchedForwardKinematics::kPoseValues;
constexpr double kBatchInfinity = std::numeric_limits<double>::infinity();
using PairKind = PartPairKind;

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
/// BatchScratch::partWork's list for K), by K's kernel, in lanes first .. first + width(V) - 1: into
/// BatchScratch::partPairGaps, over the bounding spheres' gap there (two capsules' replaces it; it
/// is exact).
template <PairKind K, class V>
[[gnu::always_inline]] inline void partPairGaps(const CheckerModel& model, BatchScratch& scratch, std::uint32_t count,
                                                int first, bool tight) {
  const PartPairTable& table = model.partPairs();
  const std::uint32_t* work = scratch.partWork.data() + table.kindBegin[static_cast<int>(K)];
  const double* placed = scratch.partLanes.data() + first;
  for (std::uint32_t w = 0; w < count; ++w) {
    const std::uint32_t k = work[w];
    const PartPair& pp = table.pairs[k];
    const ConvexPart &sa = table.shapes[pp.indexA], &sb = table.shapes[pp.indexB];
    const double* a = placed + static_cast<std::size_t>(pp.indexA) * kPartValues * L;
    const double* b = placed + static_cast<std::size_t>(pp.indexB) * kPartValues * L;
    double* g = scratch.partPairGaps.data() + first + static_cast<std::size_t>(k) * L;
    if constexpr (K == PairKind::CapsuleCapsule)
      lanes::store(g, capsuleCapsuleGap<V>(sa, a, pp.inverseA, sb, b, pp.inverseB));
    else
      lanes::store(g, lanes::max(lanes::load<V>(g), solidPairGap<K, V>(sa, a, sb, b, model.band(), tight)));
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

// Obstacle o (of kind K) against every moving link's bound, a whole subtree at a time where its
// sphere is clear of the obstacle: the sphere around a link's bound centre that holds its
// descendants' bounds (BatchScratch::subtreeLanes, radius grown by a relative 1e-12 against
// rounding).
template <ConvexPart::Kind K, class V>
[[gnu::always_inline]] inline void screenObstacleOf(const CheckerModel& model, BatchScratch& scratch, std::size_t o,
                                                    int first, bool tight) {
  using lanes::load;
  using lanes::store;
  const GeometricLinks& geometric = model.geometricLinks();
  const double band = model.band();
  const std::size_t selfCount = model.selfPairs().size(), linkCount = geometric.size();
  const ConvexPart& obstacle = model.obstacles()[o].part;
  const double* subtree = scratch.subtreeLanes.data() + first;
  double* obstacleGaps = scratch.pairLaneGaps.data() + first + (selfCount + o * linkCount) * L;
  char* obstacleNear = scratch.pairNear.data() + selfCount + o * linkCount;
  for (std::size_t i = 0; i < linkCount;) {
    const auto end = static_cast<std::size_t>(geometric.subtreeEnd[i]);
    const Point<V> centre =
        pointAt<V>(scratch.boundLanes.data() + static_cast<std::size_t>(geometric.links[i]) * 3 * L + first);
    if (!tight && end > i + 1) {
      const V whole = sphereGap<K>(obstacle, centre, load<V>(subtree + i * L) * (1.0 + 1e-12));
      if (!(lanes::lowest(whole) <= band)) {
        for (; i < end; ++i) store(obstacleGaps + i * L, whole), obstacleNear[i] = 0;
        continue;
      }
    }
    const V gap = sphereGap<K>(obstacle, centre, lanes::splat<V>(geometric.boundRadius[i]));
    store(obstacleGaps + i * L, gap);
    obstacleNear[i] = lanes::lowest(gap) <= band;
    ++i;
  }
}

// Lanes first .. first + width(V) - 1, in passes that keep the data-dependent branches out of the
// long loops: (1) every pair's bounds; (2) for the pairs whose bounds meet in some lane, their links
// placed, every part pair's bounding spheres, then where those meet the kernel of the pair's kinds
// (one loop per kind of pair, PartPairKind), then each pair's smallest part gap; (3) the safe
// value. Leaves each pair's gap (a lower bound; +inf in a lane left open) in pairLaneGaps, the
// smallest gap * share in laneSafe, and in laneScalar the pairs each lane must test alone. Lanes
// from `count` on repeat the last configuration: they are computed, never reported.
template <class V>
[[gnu::always_inline]] inline void screenLanesOf(const CheckerModel& model, BatchScratch& scratch,
                                                 const MotionShares& shares, const double* poses, int count, int first,
                                                 bool tight) {
  using lanes::load;
  using lanes::store;
  constexpr int W = lanes::widthOf<V>;
  const SelfPairs& selfPairs = model.selfPairs();
  const GeometricLinks& geometric = model.geometricLinks();
  const PartPairTable& table = model.partPairs();
  const std::vector<LinkParts>& links = model.links();
  const std::vector<ObstaclePart>& obstacles = model.obstacles();
  const double band = model.band();
  const std::size_t selfCount = selfPairs.size(), linkCount = geometric.size(), pairs = model.pairCount();
  lanes::MaskOf<V> active;
  for (int l = 0; l < W; ++l) active[l] = first + l < count ? -1 : 0;
  poses += first;
  double* gaps = scratch.pairLaneGaps.data() + first;
  double* partGaps = scratch.partPairGaps.data() + first;
  const auto part = [&](std::uint32_t index) {
    return scratch.partLanes.data() + static_cast<std::size_t>(index) * kPartValues * L + first;
  };
  const auto bound = [&](int link) {
    return pointAt<V>(scratch.boundLanes.data() + static_cast<std::size_t>(link) * 3 * L + first);
  };
  const auto place = [&](int link) {
    const auto l = static_cast<std::size_t>(link);
    if (scratch.partLanesPlaced[l]) return;
    scratch.partLanesPlaced[l] = 1;
    const double* m = poses + l * kBatchValues * L;
    const auto& parts = links[l].parts;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const ConvexPart& shape = parts[i];
      double* out = part(static_cast<std::uint32_t>(model.partOffset()[l]) + static_cast<std::uint32_t>(i));
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
  std::fill(scratch.partLanesPlaced.begin(), scratch.partLanesPlaced.end(), 0);
  for (int l : model.boundLinks())
    storePoint(scratch.boundLanes.data() + static_cast<std::size_t>(l) * 3 * L + first,
               transformed<V>(poses + static_cast<std::size_t>(l) * kBatchValues * L,
                              links[static_cast<std::size_t>(l)].boundCentre));
  for (std::size_t p = 0; p < selfCount; ++p) {
    const Point<V> d = bound(selfPairs.a[p]) - bound(selfPairs.b[p]);
    const V gap = lanes::sqrtBelow(lanes::dot(d, d)) - selfPairs.radiusSum[p];
    store(gaps + p * L, gap);
    scratch.pairNear[p] = lanes::lowest(gap) <= band;
  }
  // Against the obstacles: each obstacle's subtree radii first.
  double* subtree = scratch.subtreeLanes.data() + first;
  for (std::size_t i = 0; i < linkCount; ++i) store(subtree + i * L, lanes::splat<V>(geometric.boundRadius[i]));
  for (std::size_t i = linkCount; i-- > 0;) {
    const int parent = geometric.parent[i];
    if (parent < 0) continue;
    const Point<V> d = bound(geometric.links[i]) - bound(geometric.links[static_cast<std::size_t>(parent)]);
    double* r = subtree + static_cast<std::size_t>(parent) * L;
    store(r, lanes::max(load<V>(r), lanes::sqrt(lanes::dot(d, d)) + load<V>(subtree + i * L)));
  }
  for (std::size_t o = 0; o < obstacles.size(); ++o) switch (obstacles[o].part.kind) {
      case ConvexPart::Kind::Capsule:
        screenObstacleOf<ConvexPart::Kind::Capsule, V>(model, scratch, o, first, tight);
        break;
      case ConvexPart::Kind::Box:
        screenObstacleOf<ConvexPart::Kind::Box, V>(model, scratch, o, first, tight);
        break;
      case ConvexPart::Kind::Cylinder:
        screenObstacleOf<ConvexPart::Kind::Cylinder, V>(model, scratch, o, first, tight);
        break;
      case ConvexPart::Kind::Triangle:
        break;  // only the exact checker's mesh route holds triangles
    }

  // (2) Parts.
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!scratch.pairNear[pair]) continue;
    if (pair < selfCount) {
      place(selfPairs.a[pair]);
      place(selfPairs.b[pair]);
    } else {
      place(geometric.links[(pair - selfCount) % linkCount]);
    }
  }
  std::uint32_t counts[kPartPairKinds] = {};  // of partWork's lists
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!scratch.pairNear[pair]) continue;
    for (std::uint32_t k = table.pairBegin[pair]; k < table.pairBegin[pair + 1]; ++k) {
      const PartPair& pp = table.pairs[k];
      const Point<V> d = pointAt<V>(part(pp.indexA) + kPartBound * L) - pointAt<V>(part(pp.indexB) + kPartBound * L);
      const V spheres = lanes::sqrtBelow(lanes::dot(d, d)) -
                        (table.shapes[pp.indexA].boundRadius + table.shapes[pp.indexB].boundRadius);
      store(partGaps + static_cast<std::size_t>(k) * L, spheres);
      const bool meet = tight || lanes::lowest(spheres) <= band;  // tight: every part pair measured
      const auto kind = static_cast<int>(pp.kind);
      scratch.partWork[table.kindBegin[kind] + counts[kind]] = k;
      counts[kind] += meet;
    }
  }
  const auto at = [](PairKind kind) { return static_cast<int>(kind); };
  partPairGaps<PairKind::CapsuleCapsule, V>(model, scratch, counts[at(PairKind::CapsuleCapsule)], first, tight);
  partPairGaps<PairKind::CapsuleBox, V>(model, scratch, counts[at(PairKind::CapsuleBox)], first, tight);
  partPairGaps<PairKind::CapsuleCylinder, V>(model, scratch, counts[at(PairKind::CapsuleCylinder)], first, tight);
  partPairGaps<PairKind::BoxBox, V>(model, scratch, counts[at(PairKind::BoxBox)], first, tight);
  partPairGaps<PairKind::BoxCylinder, V>(model, scratch, counts[at(PairKind::BoxCylinder)], first, tight);
  partPairGaps<PairKind::CylinderBox, V>(model, scratch, counts[at(PairKind::CylinderBox)], first, tight);
  partPairGaps<PairKind::CylinderCylinder, V>(model, scratch, counts[at(PairKind::CylinderCylinder)], first, tight);
  for (std::size_t pair = 0; pair < pairs; ++pair) {
    if (!scratch.pairNear[pair]) continue;
    V partsGap = lanes::splat<V>(kBatchInfinity);
    for (std::uint32_t k = table.pairBegin[pair]; k < table.pairBegin[pair + 1]; ++k)
      partsGap = lanes::min(partsGap, load<V>(partGaps + static_cast<std::size_t>(k) * L));
    const V gap = load<V>(gaps + pair * L);
    const auto near = gap <= band, alone = (partsGap <= band) & near & active;
    store(gaps + pair * L,
          lanes::select<V>(alone, lanes::splat<V>(kBatchInfinity), lanes::select<V>(near, partsGap, gap)));
    if (lanes::any(alone))
      for (unsigned b = lanes::bits(alone); b; b &= b - 1) scratch.laneScalar[first + __builtin_ctz(b)].push_back(pair);
  }

  // (3) The safe value.
  V safe = lanes::splat<V>(kBatchInfinity);
  for (std::size_t p = 0; p < selfCount; ++p) safe = lanes::min(safe, load<V>(gaps + p * L) * shares.pair[p]);
  for (std::size_t o = 0; o < obstacles.size(); ++o)
    for (std::size_t i = 0; i < linkCount; ++i)
      safe = lanes::min(safe, load<V>(gaps + (selfCount + o * linkCount + i) * L) * shares.link[i]);
  store(scratch.laneSafe + first, safe);
}

// The lane-vector stage at each SIMD level, built for that instruction set: fills pairLaneGaps,
// laneSafe and laneScalar. `tight`: every pair's gap as tight as these tests get it (the caller
// keeps them, as motion-check certificates), not just tight enough to prove.
[[gnu::target("avx512f")]] void screenAvx512(const CheckerModel& model, CheckerScratch& scratch, const double* poses,
                                             int count, bool tight) {
  screenLanesOf<lanes::Vec<8>>(model, scratch.batch(), scratch.shares(), poses, count, 0, tight);
}
[[gnu::target("avx2")]] void screenAvx2(const CheckerModel& model, CheckerScratch& scratch, const double* poses,
                                        int count, bool tight) {
  for (int first = 0; first < count; first += 4)
    screenLanesOf<lanes::Vec<4>>(model, scratch.batch(), scratch.shares(), poses, count, first, tight);
}
void screenSse2(const CheckerModel& model, CheckerScratch& scratch, const double* poses, int count, bool tight) {
  for (int first = 0; first < count; first += 2)
    screenLanesOf<lanes::Vec<2>>(model, scratch.batch(), scratch.shares(), poses, count, first, tight);
}

void screenLanes(const CheckerModel& model, CheckerScratch& scratch, SimdLevel level, const double* poses, int count,
                 bool tight) {
  switch (level) {
    case SimdLevel::avx512:
      return screenAvx512(model, scratch, poses, count, tight);
    case SimdLevel::avx2:
      return screenAvx2(model, scratch, poses, count, tight);
    case SimdLevel::sse2:
      break;
  }
  screenSse2(model, scratch, poses, count, tight);
}

}  // namespace

int screenBatch(const CheckerModel& model, CheckerScratch& scratch, SimdLevel level,
                const Configuration* const* configurations, int count, const double* poses, bool* valid, double* safe,
                double* pairGaps, const bool* stopAt) {
  const SelfPairs& selfPairs = model.selfPairs();
  const GeometricLinks& geometric = model.geometricLinks();
  const std::size_t selfCount = selfPairs.size(), linkCount = geometric.size(), pairs = model.pairCount();
  BatchScratch& batch = scratch.batch();
  const MotionShares& shares = scratch.shares();
  FastCheckStatistics& statistics = scratch.statistics();
  std::vector<Flag>& uncertain = scratch.uncertain();
  if (model.staticCollisions().any(false)) {
    for (int lane = 0; lane < count; ++lane) valid[lane] = false, safe[lane] = 0.0, ++statistics.provenColliding;
    return stopAt && !*stopAt ? 0 : count;
  }
  for (int lane = 0; lane < count; ++lane) batch.laneScalar[lane].clear();
  screenLanes(model, scratch, level, poses, count, pairGaps != nullptr);

  // Lane by lane: the pairs the lane vectors left open, FCL for those within the band, the verdict.
  for (int lane = 0; lane < count; ++lane) {
    beginLane(model, scratch, poses, L, lane);
    uncertain.clear();
    bool overlapping = false;
    double laneSafe = batch.laneSafe[lane];
    for (const std::size_t pair : batch.laneScalar[lane]) {
      const bool self = pair < selfCount;
      const std::size_t i = self ? 0 : (pair - selfCount) % linkCount, o = self ? 0 : (pair - selfCount) / linkCount;
      const int a = self ? selfPairs.a[pair] : geometric.links[i], b = self ? selfPairs.b[pair] : static_cast<int>(o);
      // linkPairContact reads b's bound
      if (self && !scratch.lane().boundPlaced[static_cast<std::size_t>(b)]) placeBound(model, scratch, b);
      double gap;
      const Outcome outcome =
          self ? linkPairContact(model, scratch, a, b, gap) : linkObstacleContact(model, scratch, a, o, gap);
      if (outcome == Outcome::Overlapping) {
        overlapping = true;
        break;
      }
      if (outcome != Outcome::Apart) {
        uncertain.push_back(Flag{self, a, b, outcome});
        gap = 0.0;
      }
      batch.pairLaneGaps[pair * L + static_cast<std::size_t>(lane)] = gap;
      laneSafe = std::min(laneSafe, gap * (self ? shares.pair[pair] : shares.link[i]));
    }
    safe[lane] = 0.0;
    if (overlapping) {
      ++statistics.provenColliding;
      valid[lane] = false;
      if (stopAt && !*stopAt) return lane;
      continue;
    }
    if (pairGaps)
      for (std::size_t pair = 0; pair < pairs; ++pair)
        pairGaps[static_cast<std::size_t>(lane) * pairs + pair] =
            batch.pairLaneGaps[pair * L + static_cast<std::size_t>(lane)];
    if (uncertain.empty()) {
      ++statistics.provenFree;
      valid[lane] = true;
      safe[lane] = laneSafe;
    } else {
      valid[lane] = confirmUncertain(model, scratch, *configurations[lane]);
    }
    if (stopAt && valid[lane] == *stopAt) return lane;
  }
  return count;
}

}  // namespace pmdplan::fast
