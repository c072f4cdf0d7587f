// FastCollisionChecker::screenBatch: the geometric stages for kLanes configurations at once, on
// lane vectors (lane_vector.hpp) as wide as the running CPU's: all eight lanes in one AVX-512
// register, or two passes of four (AVX2), or four of two (SSE2). For every pair: the link bounds
// (a whole subtree of links against an obstacle first); where those meet, the parts' bounding
// spheres; where those meet, the parts themselves — capsules by their exact distance, boxes and
// cylinders by separating axes (face normals and cylinder axes) and a segment-cylinder bound. Only
// a lane whose pair none of these proves apart goes on, alone, to the one-configuration tests
// (linkPairContact / linkObstacleContact, then FCL).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "lane_distances.hpp"
#include "pmdplan/collision/convex_distance.hpp"
#include "pmdplan/collision/fast_collision_checker.hpp"

namespace pmdplan {
namespace {

using lanes::Point;
constexpr int L = FastCollisionChecker::kLanes;
constexpr int kValues = BatchedForwardKinematics::kPoseValues;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// A placed part, [value][lane]: its core's a (or centre) and b, its rotation (row-major), its
/// bounding sphere's centre, its outer capsule's ends.
constexpr int kPartAxes = 6, kPartBound = 15, kPartOuter = 18, kPartValues = 24;

template <class V>
[[gnu::always_inline]] inline Point<V> pointAt(const double* p) {
  return lanes::loadPoint<V>(p, L);
}

template <class V>
[[gnu::always_inline]] inline void storePoint(double* out, const Point<V>& p) {
  lanes::store(out, p.x), lanes::store(out + L, p.y), lanes::store(out + 2 * L, p.z);
}

/// Row r of pose * p lane by lane; `m` is a link's pose, [value][lane]. A function always inlined,
/// not a lambda: a lambda's body is a function of its own, built for the baseline instruction set
/// whatever the kernel it sits in, and a vector it returns to an AVX kernel comes back where the
/// baseline ABI puts it, not where the kernel reads it (garbage lanes wherever the compiler does
/// not inline the lambda: clang at -O1, the sanitizer build, so checks called free what collides).
template <class V>
[[gnu::always_inline]] inline V transformedRow(const double* m, const double* p, int r) {
  using lanes::load;
  return load<V>(m + (r * 3) * L) * p[0] + load<V>(m + (r * 3 + 1) * L) * p[1] + load<V>(m + (r * 3 + 2) * L) * p[2] +
         load<V>(m + (9 + r) * L);
}
template <class V>
[[gnu::always_inline]] inline Point<V> transformed(const double* m, const double* p) {
  return {transformedRow<V>(m, p, 0), transformedRow<V>(m, p, 1), transformedRow<V>(m, p, 2)};
}

/// Axis k (a column of the rotation) of a placed part.
template <class V>
[[gnu::always_inline]] inline Point<V> axisOf(const double* part, int k) {
  const double* axes = part + kPartAxes * L;
  return {lanes::load<V>(axes + k * L), lanes::load<V>(axes + (3 + k) * L), lanes::load<V>(axes + (6 + k) * L)};
}

/// Centre and half width of a placed part's projection on the unit direction n.
template <class V>
[[gnu::always_inline]] inline void project(const ConvexPart& shape, const double* part, const Point<V>& n, V& centre,
                                           V& halfWidth) {
  using lanes::abs;
  using lanes::dot;
  const Point<V> a = pointAt<V>(part);
  if (shape.kind == ConvexPart::Kind::Capsule) {
    const V pa = dot(n, a), pb = dot(n, pointAt<V>(part + 3 * L));
    centre = 0.5 * (pa + pb), halfWidth = 0.5 * abs(pb - pa) + shape.radius;
    return;
  }
  centre = dot(n, a);
  if (shape.kind == ConvexPart::Kind::Box) {
    halfWidth = shape.half[0] * abs(dot(n, axisOf<V>(part, 0))) + shape.half[1] * abs(dot(n, axisOf<V>(part, 1))) +
                shape.half[2] * abs(dot(n, axisOf<V>(part, 2)));
  } else {
    const V w = abs(dot(n, axisOf<V>(part, 2)));
    halfWidth = shape.half[1] * w + shape.half[0] * lanes::sqrt(lanes::max(lanes::splat<V>(0.0), 1.0 - w * w));
  }
}

/// The largest gap between the parts' projections on the face normals of their boxes and the axes
/// of their cylinders: a lower bound on their distance (separating axes, as faceSeparation). On
/// its own axes a part's half width is its half extent. Unless `tight`, the second part's axes are
/// tried only if the first part's leave some lane unproven (a looser bound, proof enough).
template <class V>
[[gnu::always_inline]] inline V faceSeparation(const ConvexPart& shapeA, const double* a, const ConvexPart& shapeB,
                                               const double* b, double band, bool tight) {
  V best = lanes::splat<V>(-kInfinity);
  const auto alongAxesOf = [&](const ConvexPart& own, const double* ownLanes, const ConvexPart& other,
                               const double* otherLanes) {
    if (own.kind == ConvexPart::Kind::Capsule) return;
    const V ownCentre[3] = {pointAt<V>(ownLanes).x, pointAt<V>(ownLanes).y, pointAt<V>(ownLanes).z};
    for (int k = own.kind == ConvexPart::Kind::Box ? 0 : 2; k < 3; ++k) {
      const Point<V> n = axisOf<V>(ownLanes, k);
      V centre, halfWidth;
      project(other, otherLanes, n, centre, halfWidth);
      const V ownHalf = lanes::splat<V>(own.kind == ConvexPart::Kind::Box ? own.half[k] : own.half[1]);
      best = lanes::max(best, lanes::abs(n.x * ownCentre[0] + n.y * ownCentre[1] + n.z * ownCentre[2] - centre) -
                                  ownHalf - halfWidth);
    }
  };
  alongAxesOf(shapeA, a, shapeB, b);
  if (!tight && shapeA.kind != ConvexPart::Kind::Capsule && !lanes::any(best <= band)) return best;
  alongAxesOf(shapeB, b, shapeA, a);
  return best;
}

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

/// sphereGap lane by lane: from spheres (centres c, radius r) to a part fixed in the world; a lower
/// bound (sqrtBelow).
template <class V>
[[gnu::always_inline]] inline V obstacleSphereGap(const ConvexPart& part, const Point<V>& c, V r) {
  using lanes::abs;
  using lanes::max;
  const Point<V> d = {c.x - part.a[0], c.y - part.a[1], c.z - part.a[2]};
  if (part.kind == ConvexPart::Kind::Capsule) {
    const double ex = part.b[0] - part.a[0], ey = part.b[1] - part.a[1], ez = part.b[2] - part.a[2];
    const double length2 = ex * ex + ey * ey + ez * ez, inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
    const V t = lanes::clamp01((d.x * ex + d.y * ey + d.z * ez) * inverse);
    const Point<V> q = {d.x - t * ex, d.y - t * ey, d.z - t * ez};
    return lanes::sqrtBelow(lanes::dot(q, q)) - (part.radius + r);
  }
  const double* m = part.axes;  // local coordinates: the rotation transposed
  const V u = m[0] * d.x + m[3] * d.y + m[6] * d.z, v = m[1] * d.x + m[4] * d.y + m[7] * d.z,
          w = m[2] * d.x + m[5] * d.y + m[8] * d.z;
  const V zero = lanes::splat<V>(0.0);
  if (part.kind == ConvexPart::Kind::Box) {
    const V ou = max(abs(u) - part.half[0], zero), ov = max(abs(v) - part.half[1], zero),
            ow = max(abs(w) - part.half[2], zero);
    return lanes::sqrtBelow(ou * ou + ov * ov + ow * ow) - r;
  }
  const V radial = max(lanes::sqrt(u * u + v * v) - part.half[0], zero), axial = max(abs(w) - part.half[1], zero);
  return lanes::sqrtBelow(radial * radial + axial * axial) - r;
}

}  // namespace

void FastCollisionChecker::prepareLanes() {
  const std::size_t obstacleBase = worldParts_.size();
  boundLanes_.assign(links_.size() * 3 * L, 0.0);
  partLanes_.assign((obstacleBase + obstacles_.size()) * kPartValues * L, 0.0);
  partLanesPlaced_.assign(links_.size(), 0);
  pairLaneGaps_.assign(pairCount() * L, 0.0);
  pairNear_.assign(pairCount(), 0);
  subtreeLanes_.assign(geometricLinks_.size() * L, 0.0);
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const ConvexPart& part = obstacles_[o].part;
    double* out = partLanes_.data() + (obstacleBase + o) * kPartValues * L;
    const auto spread = [&](int at, const double* values, int count) {
      for (int v = 0; v < count; ++v)
        for (int l = 0; l < L; ++l) out[(at + v) * L + l] = values[v];
    };
    spread(0, part.a, 3);
    spread(3, part.b, 3);
    spread(kPartAxes, part.axes, 9);
    spread(kPartBound, part.boundCentre, 3);
    spread(kPartOuter, part.outerA, 3);
    spread(kPartOuter + 3, part.outerB, 3);
  }
  // Every part, then every pair's part pairs in pair order.
  partShapes_.clear();
  for (const auto& link : links_) partShapes_.insert(partShapes_.end(), link.parts.begin(), link.parts.end());
  for (const auto& obstacle : obstacles_) partShapes_.push_back(obstacle.part);
  const auto add = [&](std::uint32_t a, std::uint32_t b) {
    const ConvexPart &pa = partShapes_[a], &pb = partShapes_[b];
    partPairs_.push_back({a, b, pa.kind == ConvexPart::Kind::Capsule && pb.kind == ConvexPart::Kind::Capsule,
                          lanes::inverseSquaredLength(pa.a, pa.b), lanes::inverseSquaredLength(pb.a, pb.b)});
  };
  const auto partsOf = [&](int link) {
    const auto first = static_cast<std::uint32_t>(partOffset_[static_cast<std::size_t>(link)]);
    return std::pair{first, first + static_cast<std::uint32_t>(links_[static_cast<std::size_t>(link)].parts.size())};
  };
  partPairs_.clear();
  pairPartsBegin_.assign(1, 0);
  for (std::size_t p = 0; p < selfPairs_.size(); ++p) {
    const auto [beginA, endA] = partsOf(pairA_[p]);
    const auto [beginB, endB] = partsOf(pairB_[p]);
    for (std::uint32_t i = beginA; i < endA; ++i)
      for (std::uint32_t j = beginB; j < endB; ++j) add(i, j);
    pairPartsBegin_.push_back(static_cast<std::uint32_t>(partPairs_.size()));
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    for (const int link : geometricLinks_) {
      const auto [begin, end] = partsOf(link);
      for (std::uint32_t k = begin; k < end; ++k) add(k, static_cast<std::uint32_t>(obstacleBase + o));
      pairPartsBegin_.push_back(static_cast<std::uint32_t>(partPairs_.size()));
    }
  partPairGaps_.assign(partPairs_.size() * L, 0.0);
  capsuleWork_.assign(partPairs_.size(), 0);
  faceWork_.assign(partPairs_.size(), 0);
}

// Lanes first .. first + width(V) - 1, in passes that keep the data-dependent branches out of the
// long loops: (1) every pair's bounds; (2) for the pairs whose bounds meet in some lane, their links
// placed, every part pair's bounding spheres, then where those meet the exact capsule distance or
// the separating axes (each kind in one loop), then each pair's smallest part gap; (3) the safe
// value. Leaves each pair's gap (a lower bound; +inf in a lane left open) in pairLaneGaps_, the
// smallest gap * share in laneSafe_, and in laneScalar_ the pairs each lane must test alone. Lanes
// from `count` on repeat the last configuration: they are computed, never reported.
template <class V>
[[gnu::always_inline]] inline void FastCollisionChecker::screenLanesOf(const double* poses, int count, int first,
                                                                       bool tight) {
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

[[gnu::target("avx512f")]] void FastCollisionChecker::screenAvx512(FastCollisionChecker& c, const double* poses,
                                                                   int count, bool tight) {
  c.screenLanesOf<lanes::Vec<8>>(poses, count, 0, tight);
}
[[gnu::target("avx2")]] void FastCollisionChecker::screenAvx2(FastCollisionChecker& c, const double* poses, int count,
                                                              bool tight) {
  for (int first = 0; first < count; first += 4) c.screenLanesOf<lanes::Vec<4>>(poses, count, first, tight);
}
void FastCollisionChecker::screenSse2(FastCollisionChecker& c, const double* poses, int count, bool tight) {
  for (int first = 0; first < count; first += 2) c.screenLanesOf<lanes::Vec<2>>(poses, count, first, tight);
}

void FastCollisionChecker::setSimdLevel(SimdLevel level) {
  const bool known = level == SimdLevel::sse2 || level == SimdLevel::avx2 || level == SimdLevel::avx512;
  if (!known || laneWidth(level) > laneWidth(widestSimdLevel()))
    throw std::invalid_argument(std::string("SIMD level ") + (known ? simdLevelName(level) : "unknown") +
                                ": this CPU runs sse2 to " + simdLevelName(widestSimdLevel()));
  simdLevel_ = level;
}

void FastCollisionChecker::screenLanes(const double* poses, int count, bool tight) {
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

void FastCollisionChecker::screenBatch(const Configuration* const* configurations, int count, const double* poses,
                                       bool* valid, double* safe, double* pairGaps) {
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

}  // namespace pmdplan
