// The fast checker's scalar screen: the geometric stages of one configuration (isValid,
// isArmValid, a lone state of checkBatch, screen) — the link bounds of every pair in branch-free
// passes (the environment's, then the robot's own), then the narrow phase (narrow_phase.cpp) for the pairs whose bounds
// meet, then FCL for the pairs it leaves uncertain.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "checker_state.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan::fast {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

// The geometric stages of one configuration (lane `lane` of poses laid out with `stride` lanes).
// onFlag(Flag) is called for every pair not proven apart and returns true to stop. Returns the
// safe displacement (see ScreenResult) when every pair was proven apart, 0 when some were
// flagged, -1 when stopped. With pairGaps, every pair's gap is written there (0 when flagged).
template <class OnFlag>
double CheckerState::screenLane(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag,
                                double* pairGaps) {
  beginLane(poses, stride, lane);
  for (int l : boundLinks_) placeBound(l);
  double safe = kInfinity;
  bool flagged = false;
  const std::size_t selfCount = selfPairs_.size();  // the pairGaps layout: self pairs, then link x obstacle

  // Environment first: every moving link against every obstacle (static links were decided once),
  // the link bounds first in one pass per obstacle. Most configurations a planner draws and rejects
  // put a finger or the palm into an object, so a proven overlap here ends the check before the
  // many close finger pairs of the self pass are measured; a free configuration needs both passes
  // anyway. Skipped for the arm alone.
  if (!armOnly) {
    const std::size_t linkCount = geometricLinks_.size();
    for (std::size_t i = 0; i < linkCount; ++i) {
      const auto l = static_cast<std::size_t>(geometricLinks_[i]);
      geometricX_[i] = boundX_[l], geometricY_[i] = boundY_[l], geometricZ_[i] = boundZ_[l];
    }
    for (std::size_t o = 0; o < obstacles_.size(); ++o)
      sphereGaps(obstacles_[o].part, geometricX_.data(), geometricY_.data(), geometricZ_.data(),
                 geometricBoundR_.data(), static_cast<int>(linkCount), obstacleGaps_.data() + o * linkCount);
    for (std::size_t o = 0; o < obstacles_.size(); ++o) {
      const double* gaps = obstacleGaps_.data() + o * linkCount;
      for (std::size_t i = 0; i < linkCount; ++i) {
        double gap = gaps[i];
        if (!(gap > band_)) {
          const int l = geometricLinks_[i];
          const Outcome outcome = linkObstacleContact(l, o, gap);
          if (outcome != Outcome::Apart) {
            flagged = true;
            if (pairGaps) pairGaps[selfCount + o * linkCount + i] = 0.0;
            if (onFlag(Flag{false, l, static_cast<int>(o), outcome})) return -1.0;
            continue;
          }
        }
        if (pairGaps) pairGaps[selfCount + o * linkCount + i] = gap;
        safe = std::min(safe, gap * linkShare_[i]);
      }
    }
  }

  // Self: the link bounds of every pair in one branch-free pass (it vectorises), then the pairs
  // whose bounds come within the band, part by part.
  {
    const int* pa = pairA_.data();
    const int* pb = pairB_.data();
    const double *bx = boundX_.data(), *by = boundY_.data(), *bz = boundZ_.data();
    double* __restrict dx = pairDx_.data();
    double* __restrict dy = pairDy_.data();
    double* __restrict dz = pairDz_.data();
    for (std::size_t p = 0; p < selfCount; ++p)  // gathers
      dx[p] = bx[pa[p]] - bx[pb[p]], dy[p] = by[pa[p]] - by[pb[p]], dz[p] = bz[pa[p]] - bz[pb[p]];
    const double* sum = pairRadiusSum_.data();
    double* __restrict gaps = pairGaps_.data();
    for (std::size_t p = 0; p < selfCount; ++p)
      gaps[p] = std::sqrt(dx[p] * dx[p] + dy[p] * dy[p] + dz[p] * dz[p]) - sum[p];
  }
  for (std::size_t p = 0; p < selfCount; ++p) {
    if (armOnly && !pairIsArm_[p]) continue;
    double gap = pairGaps_[p];
    if (!(gap > band_)) {
      const auto [a, b] = selfPairs_[p];
      const Outcome outcome = linkPairContact(a, b, gap);
      if (outcome != Outcome::Apart) {
        flagged = true;
        if (pairGaps) pairGaps[p] = 0.0;
        if (onFlag(Flag{true, a, b, outcome})) return -1.0;
        continue;
      }
    }
    if (pairGaps) pairGaps[p] = gap;
    safe = std::min(safe, gap * pairShare_[p]);
  }
  return flagged ? 0.0 : safe;
}

bool CheckerState::decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly,
                          double* safeDisplacement, double* pairGaps) {
  if (safeDisplacement) *safeDisplacement = 0.0;
  if (armOnly ? !staticArmSelfCollisions_.empty()
              : !(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    ++statistics_.provenColliding;
    return false;
  }
  // Proven overlaps stop at once; uncertain pairs wait, since a proven overlap may still come.
  uncertain_.clear();
  const double safe = screenLane(
      poses, stride, lane, armOnly,
      [&](const Flag& flag) {
        if (flag.outcome == Outcome::Overlapping) return true;
        uncertain_.push_back(flag);
        return false;
      },
      pairGaps);
  if (safe < 0.0) {
    ++statistics_.provenColliding;
    return false;
  }
  if (uncertain_.empty()) {
    ++statistics_.provenFree;
    if (safeDisplacement) *safeDisplacement = safe;
    return true;
  }
  return confirmUncertain(q);
}

ScreenResult CheckerState::screen(const Configuration& q, bool armOnly) {
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  kinematics_.computeOne(q.data(), poseScratch_.data());
  ScreenResult result;
  result.overlappingSelf = armOnly ? staticArmSelfCollisions_ : staticSelfCollisions_;
  if (!armOnly) result.overlappingObstacle = staticEnvironmentCollisions_;
  const double safe = screenLane(poseScratch_.data(), 1, 0, armOnly, [&](const Flag& flag) {
    const bool overlapping = flag.outcome == Outcome::Overlapping;
    if (flag.self)
      (overlapping ? result.overlappingSelf : result.uncertainSelf).emplace_back(flag.a, flag.b);
    else
      (overlapping ? result.overlappingObstacle : result.uncertainObstacle)
          .emplace_back(flag.a, static_cast<std::size_t>(flag.b));
    return false;
  });
  result.safeDisplacement = result.provenFree() ? std::max(safe, 0.0) : 0.0;
  return result;
}

}  // namespace pmdplan::fast
