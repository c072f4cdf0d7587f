// FastCollisionChecker::screenBatch: the geometric stages for kLanes configurations at once. Each
// number of the broad phase and of the parts' outer-capsule tests is an array over the lanes (the
// poses already come that way from BatchedForwardKinematics), so one SIMD instruction serves all
// configurations; only the few part pairs the capsules cannot clear go on, lane by lane, to the
// exact tests of the one-configuration path.
#include <algorithm>
#include <cmath>
#include <limits>

#include "pmdplan/collision/convex_distance.hpp"
#include "pmdplan/collision/fast_collision_checker.hpp"

namespace pmdplan {
namespace {

constexpr int L = FastCollisionChecker::kLanes;
constexpr int kValues = BatchedForwardKinematics::kPoseValues;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
static_assert(L == kSegmentLanes, "the batched capsule tests run over the kinematics' lanes");

/// out = pose * p for every lane; p in the link frame, out as x[lane], y[lane], z[lane].
void transformLanes(const double* poses, int link, const double* p, double* out) {
  const double* m = poses + static_cast<std::size_t>(link) * kValues * L;
  for (int r = 0; r < 3; ++r)
    for (int l = 0; l < L; ++l) out[r * L + l] = m[(r * 3) * L + l] * p[0] + m[(r * 3 + 1) * L + l] * p[1] + m[(r * 3 + 2) * L + l] * p[2] + m[(9 + r) * L + l];
}

/// gaps[p * L + lane] = distance between the bound centres of pair p's links minus their radii.
[[gnu::target_clones("avx2", "default")]] void pairGapLanes(const double* bounds, const int* pairA, const int* pairB,
                                                            const double* radiusSum, std::size_t count, double* gaps) {
  for (std::size_t p = 0; p < count; ++p) {
    const double* ba = bounds + static_cast<std::size_t>(pairA[p]) * 3 * L;
    const double* bb = bounds + static_cast<std::size_t>(pairB[p]) * 3 * L;
    for (int l = 0; l < L; ++l) {
      const double dx = ba[l] - bb[l], dy = ba[L + l] - bb[L + l], dz = ba[2 * L + l] - bb[2 * L + l];
      gaps[p * L + l] = std::sqrt(dx * dx + dy * dy + dz * dz) - radiusSum[p];
    }
  }
}

}  // namespace

void FastCollisionChecker::placeOuterLanes(const double* poses, int link) {
  const auto l = static_cast<std::size_t>(link);
  if (outerPlaced_[l]) return;
  const auto& parts = links_[l].parts;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    double* out = outerLanes_.data() + (static_cast<std::size_t>(partOffset_[l]) + i) * 6 * L;
    transformLanes(poses, link, parts[i].outerA, out);
    transformLanes(poses, link, parts[i].outerB, out + 3 * L);
  }
  outerPlaced_[l] = 1;
}

// A lower bound on the gap between two placed parts, lanes side by side: their outer capsules'.
void FastCollisionChecker::partGapLanes(int linkA, std::size_t partA, int linkB, std::size_t partB, double* gaps) const {
  const std::size_t ka = static_cast<std::size_t>(partOffset_[static_cast<std::size_t>(linkA)]) + partA;
  const std::size_t kb = static_cast<std::size_t>(partOffset_[static_cast<std::size_t>(linkB)]) + partB;
  const double* ca = outerLanes_.data() + ka * 6 * L;
  const double* cb = outerLanes_.data() + kb * 6 * L;
  segmentDistances(ca, ca + 3 * L, cb, cb + 3 * L, gaps);
  const double radii = links_[static_cast<std::size_t>(linkA)].parts[partA].outerRadius + links_[static_cast<std::size_t>(linkB)].parts[partB].outerRadius;
  for (int l = 0; l < L; ++l) gaps[l] -= radii;
}

void FastCollisionChecker::screenBatch(const Configuration* const* configurations, int count, const double* poses, bool* valid,
                                       double* safe, double* pairGaps) {
  const std::size_t selfCount = selfPairs_.size(), linkCount = geometricLinks_.size(), pairs = pairCount();
  if (!(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    for (int lane = 0; lane < count; ++lane) valid[lane] = false, safe[lane] = 0.0, ++statistics_.provenColliding;
    return;
  }
  const auto record = [&](int lane, std::size_t pair, double gap) {
    if (pairGaps) pairGaps[static_cast<std::size_t>(lane) * pairs + pair] = gap;
  };
  for (int lane = 0; lane < count; ++lane) {
    laneSafe_[lane] = kInfinity;
    laneWork_[lane].clear();
    laneEnvironment_[lane].clear();
  }
  std::fill(outerPlaced_.begin(), outerPlaced_.end(), 0);

  // Link bounds, lane by lane side by side.
  for (int l : boundLinks_) transformLanes(poses, l, links_[static_cast<std::size_t>(l)].boundCentre, boundLanes_.data() + static_cast<std::size_t>(l) * 3 * L);

  // Self: bounds of every pair, then the outer capsules of every part pair of the pairs whose
  // bounds meet in some lane; what these cannot clear waits in laneWork_ for the exact tests.
  pairGapLanes(boundLanes_.data(), pairA_.data(), pairB_.data(), pairRadiusSum_.data(), selfCount, selfLaneGaps_.data());
  for (std::size_t p = 0; p < selfCount; ++p) {
    double gap[L];
    bool near = false;
    for (int l = 0; l < L; ++l) gap[l] = selfLaneGaps_[p * L + static_cast<std::size_t>(l)];
    for (int l = 0; l < count; ++l) near = near || !(gap[l] > band_);
    if (near) {
      const int a = pairA_[p], b = pairB_[p];
      placeOuterLanes(poses, a);
      placeOuterLanes(poses, b);
      const auto& partsA = links_[static_cast<std::size_t>(a)].parts;
      const auto& partsB = links_[static_cast<std::size_t>(b)].parts;
      double partGap[L];
      for (int l = 0; l < L; ++l) partGap[l] = kInfinity;
      bool pending[L] = {};
      for (std::size_t i = 0; i < partsA.size(); ++i)
        for (std::size_t j = 0; j < partsB.size(); ++j) {
          double d[L];
          partGapLanes(a, i, b, j, d);
          for (int l = 0; l < count; ++l) {
            if (gap[l] > band_) continue;
            if (d[l] > band_) {
              partGap[l] = std::min(partGap[l], d[l]);
            } else {
              laneWork_[l].push_back({p, static_cast<int>(i), static_cast<int>(j), 0.0});
              pending[l] = true;
            }
          }
        }
      for (int l = 0; l < count; ++l) {
        if (gap[l] > band_) continue;
        gap[l] = partGap[l];
        // A pair with part pairs left: its gap so far waits in the work list's first entry.
        if (pending[l]) laneWork_[l].push_back({p, -1, 0, partGap[l]});
      }
      for (int l = 0; l < count; ++l)
        if (pending[l]) gap[l] = -1.0;  // decided below
    }
    for (int l = 0; l < count; ++l) {
      if (gap[l] < 0.0) continue;
      record(l, p, gap[l]);
      laneSafe_[l] = std::min(laneSafe_[l], gap[l] * pairShare_[p]);
    }
  }

  // Environment: every moving link's bound against every obstacle, lanes side by side.
  for (std::size_t i = 0; i < linkCount; ++i) {
    const double* b = boundLanes_.data() + static_cast<std::size_t>(geometricLinks_[i]) * 3 * L;
    for (int l = 0; l < L; ++l)
      geometricLanesX_[i * L + l] = b[l], geometricLanesY_[i * L + l] = b[L + l], geometricLanesZ_[i * L + l] = b[2 * L + l];
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    double* gaps = obstacleLaneGaps_.data();
    sphereGaps(obstacles_[o].part, geometricLanesX_.data(), geometricLanesY_.data(), geometricLanesZ_.data(), geometricLanesR_.data(),
               static_cast<int>(linkCount * L), gaps);
    for (std::size_t i = 0; i < linkCount; ++i)
      for (int l = 0; l < count; ++l) {
        const double gap = gaps[i * L + l];
        const std::size_t pair = selfCount + o * linkCount + i;
        if (!(gap > band_)) {
          laneEnvironment_[l].push_back(pair);
          continue;
        }
        record(l, pair, gap);
        laneSafe_[l] = std::min(laneSafe_[l], gap * linkShare_[i]);
      }
  }

  // Lane by lane: the exact tests left, FCL for pairs within the band, the verdict.
  for (int lane = 0; lane < count; ++lane) {
    beginLane(poses, L, lane);
    uncertain_.clear();
    bool overlapping = false;
    const auto& work = laneWork_[lane];
    for (std::size_t w = 0; w < work.size() && !overlapping;) {
      // A link pair's part pairs, then the entry that holds the gap its other part pairs left.
      const std::size_t p = work[w].pair;
      const int a = pairA_[p], b = pairB_[p];
      placedBounds(a), placedBounds(b);
      bool uncertain = false;
      double gap = kInfinity;
      for (; work[w].partA >= 0; ++w) {
        const PartContact contact = partContact(placedPart(a, static_cast<std::size_t>(work[w].partA)),
                                                placedPart(b, static_cast<std::size_t>(work[w].partB)), band_);
        if (contact.contact == Contact::Overlapping) {
          overlapping = true;
          break;
        }
        if (contact.contact == Contact::Uncertain)
          uncertain = true;
        else
          gap = std::min(gap, contact.gap);
      }
      if (overlapping) break;
      gap = std::min(gap, work[w++].gap);
      if (uncertain) {
        uncertain_.push_back(Flag{true, a, b, Outcome::Uncertain});
        record(lane, p, 0.0);
        laneSafe_[lane] = 0.0;
      } else {
        record(lane, p, gap);
        laneSafe_[lane] = std::min(laneSafe_[lane], gap * pairShare_[p]);
      }
    }
    for (std::size_t k = 0; k < laneEnvironment_[lane].size() && !overlapping; ++k) {
      const std::size_t pair = laneEnvironment_[lane][k], i = (pair - selfCount) % linkCount, o = (pair - selfCount) / linkCount;
      double gap;
      const Outcome outcome = linkObstacleContact(geometricLinks_[i], o, gap);
      if (outcome == Outcome::Overlapping) {
        overlapping = true;
      } else if (outcome == Outcome::Uncertain) {
        uncertain_.push_back(Flag{false, geometricLinks_[i], static_cast<int>(o), outcome});
        record(lane, pair, 0.0);
        laneSafe_[lane] = 0.0;
      } else {
        record(lane, pair, gap);
        laneSafe_[lane] = std::min(laneSafe_[lane], gap * linkShare_[i]);
      }
    }
    safe[lane] = 0.0;
    if (overlapping) {
      ++statistics_.provenColliding;
      valid[lane] = false;
      continue;
    }
    if (uncertain_.empty()) {
      ++statistics_.provenFree;
      valid[lane] = true;
      safe[lane] = laneSafe_[lane];
    } else {
      valid[lane] = confirmUncertain(*configurations[lane]);
    }
  }
}

}  // namespace pmdplan
