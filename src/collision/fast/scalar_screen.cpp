// The fast checker's scalar screen (scalar_screen.hpp): the geometric stages of one configuration
// (isValid, isArmValid, a lone state of checkBatch, screen) — the link bounds of every pair in
// branch-free passes (the environment's, then the robot's own), then the narrow phase
// (narrow_phase.hpp) for the pairs whose bounds meet, then FCL for the pairs it leaves uncertain.
#include "scalar_screen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "checker_model.hpp"
#include "checker_scratch.hpp"
#include "narrow_phase.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan::fast {
namespace {

constexpr double kScalarInfinity = std::numeric_limits<double>::infinity();

// The geometric stages of one configuration (lane `lane` of poses laid out with `stride` lanes).
// onFlag(Flag) is called for every pair not proven apart and returns true to stop. Returns the
// safe displacement (see ScreenResult) when every pair was proven apart, 0 when some were
// flagged, -1 when stopped. With pairGaps, every pair's gap is written there (0 when flagged).
template <class OnFlag>
double screenLane(const CheckerModel& model, CheckerScratch& scratch, const double* poses, int stride, int lane,
                  bool armOnly, OnFlag&& onFlag, double* pairGaps) {
  beginLane(model, scratch, poses, stride, lane);
  for (int l : model.boundLinks()) placeBound(model, scratch, l);
  const LaneScratch& placed = scratch.lane();
  ScalarScratch& s = scratch.scalar();
  const MotionShares& shares = scratch.shares();
  const SelfPairs& selfPairs = model.selfPairs();
  const GeometricLinks& geometric = model.geometricLinks();
  const std::vector<ObstaclePart>& obstacles = model.obstacles();
  const double band = model.band();
  double safe = kScalarInfinity;
  bool flagged = false;
  const std::size_t selfCount = selfPairs.size();  // the pairGaps layout: self pairs, then link x obstacle

  // Environment first: every moving link against every obstacle (static links were decided once),
  // the link bounds first in one pass per obstacle. Most configurations a planner draws and rejects
  // put a finger or the palm into an object, so a proven overlap here ends the check before the
  // many close finger pairs of the self pass are measured; a free configuration needs both passes
  // anyway. Skipped for the arm alone.
  if (!armOnly) {
    const std::size_t linkCount = geometric.size();
    for (std::size_t i = 0; i < linkCount; ++i) {
      const auto l = static_cast<std::size_t>(geometric.links[i]);
      s.geometricX[i] = placed.boundX[l], s.geometricY[i] = placed.boundY[l], s.geometricZ[i] = placed.boundZ[l];
    }
    for (std::size_t o = 0; o < obstacles.size(); ++o)
      sphereGaps(obstacles[o].part, s.geometricX.data(), s.geometricY.data(), s.geometricZ.data(),
                 geometric.boundRadius.data(), static_cast<int>(linkCount), s.obstacleGaps.data() + o * linkCount);
    for (std::size_t o = 0; o < obstacles.size(); ++o) {
      const double* gaps = s.obstacleGaps.data() + o * linkCount;
      for (std::size_t i = 0; i < linkCount; ++i) {
        double gap = gaps[i];
        if (!(gap > band)) {
          const int l = geometric.links[i];
          const Outcome outcome = linkObstacleContact(model, scratch, l, o, gap);
          if (outcome != Outcome::Apart) {
            flagged = true;
            if (pairGaps) pairGaps[selfCount + o * linkCount + i] = 0.0;
            if (onFlag(Flag{false, l, static_cast<int>(o), outcome})) return -1.0;
            continue;
          }
        }
        if (pairGaps) pairGaps[selfCount + o * linkCount + i] = gap;
        safe = std::min(safe, gap * shares.link[i]);
      }
    }
  }

  // Self: the link bounds of every pair in one branch-free pass (it vectorises), then the pairs
  // whose bounds come within the band, part by part.
  {
    const int* pa = selfPairs.a.data();
    const int* pb = selfPairs.b.data();
    const double *bx = placed.boundX.data(), *by = placed.boundY.data(), *bz = placed.boundZ.data();
    double* __restrict dx = s.pairDx.data();
    double* __restrict dy = s.pairDy.data();
    double* __restrict dz = s.pairDz.data();
    for (std::size_t p = 0; p < selfCount; ++p)  // gathers
      dx[p] = bx[pa[p]] - bx[pb[p]], dy[p] = by[pa[p]] - by[pb[p]], dz[p] = bz[pa[p]] - bz[pb[p]];
    const double* sum = selfPairs.radiusSum.data();
    double* __restrict gaps = s.pairGaps.data();
    for (std::size_t p = 0; p < selfCount; ++p)
      gaps[p] = std::sqrt(dx[p] * dx[p] + dy[p] * dy[p] + dz[p] * dz[p]) - sum[p];
  }
  for (std::size_t p = 0; p < selfCount; ++p) {
    if (armOnly && !selfPairs.isArm[p]) continue;
    double gap = s.pairGaps[p];
    if (!(gap > band)) {
      const auto [a, b] = selfPairs.pairs[p];
      const Outcome outcome = linkPairContact(model, scratch, a, b, gap);
      if (outcome != Outcome::Apart) {
        flagged = true;
        if (pairGaps) pairGaps[p] = 0.0;
        if (onFlag(Flag{true, a, b, outcome})) return -1.0;
        continue;
      }
    }
    if (pairGaps) pairGaps[p] = gap;
    safe = std::min(safe, gap * shares.pair[p]);
  }
  return flagged ? 0.0 : safe;
}

}  // namespace

bool decide(const CheckerModel& model, CheckerScratch& scratch, const Configuration& q, const double* poses, int stride,
            int lane, bool armOnly, double* safeDisplacement, double* pairGaps) {
  FastCheckStatistics& statistics = scratch.statistics();
  if (safeDisplacement) *safeDisplacement = 0.0;
  if (model.staticCollisions().any(armOnly)) {
    ++statistics.provenColliding;
    return false;
  }
  // Proven overlaps stop at once; uncertain pairs wait, since a proven overlap may still come.
  std::vector<Flag>& uncertain = scratch.uncertain();
  uncertain.clear();
  const double safe = screenLane(
      model, scratch, poses, stride, lane, armOnly,
      [&](const Flag& flag) {
        if (flag.outcome == Outcome::Overlapping) return true;
        uncertain.push_back(flag);
        return false;
      },
      pairGaps);
  if (safe < 0.0) {
    ++statistics.provenColliding;
    return false;
  }
  if (uncertain.empty()) {
    ++statistics.provenFree;
    if (safeDisplacement) *safeDisplacement = safe;
    return true;
  }
  return confirmUncertain(model, scratch, q);
}

ScreenResult screen(const CheckerModel& model, CheckerScratch& scratch, const Configuration& q, bool armOnly) {
  if (q.size() != model.dof()) throw std::invalid_argument("configuration size does not match the robot");
  model.kinematics().computeOne(q.data(), scratch.poses());
  ScreenResult result;
  const StaticCollisions& fixed = model.staticCollisions();
  result.overlappingSelf = armOnly ? fixed.armSelf : fixed.self;
  if (!armOnly) result.overlappingObstacle = fixed.environment;
  const double safe = screenLane(
      model, scratch, scratch.poses(), 1, 0, armOnly,
      [&](const Flag& flag) {
        const bool overlapping = flag.outcome == Outcome::Overlapping;
        if (flag.self)
          (overlapping ? result.overlappingSelf : result.uncertainSelf).emplace_back(flag.a, flag.b);
        else
          (overlapping ? result.overlappingObstacle : result.uncertainObstacle)
              .emplace_back(flag.a, static_cast<std::size_t>(flag.b));
        return false;
      },
      nullptr);
  result.safeDisplacement = result.provenFree() ? std::max(safe, 0.0) : 0.0;
  return result;
}

}  // namespace pmdplan::fast
