// The fast checker one pair at a time (pair_tests.hpp): the links a pair needs posed, then its
// bounds, its parts (narrow_phase.cpp) and, within the band, FCL.
#include "pmdplan/collision/fast/pair_tests.hpp"

#include <stdexcept>
#include <tuple>

#include "checker_state.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan {
namespace fast {

void CheckerState::poseState(const Configuration& q, const std::size_t* pairs, std::size_t count) {
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  // Self pairs below one common link are posed relative to it; anything else in the world.
  int frame = count > 0 && pairs[0] < selfPairs_.size() ? pairFrame_[pairs[0]] : -1;
  for (std::size_t k = 1; k < count && frame >= 0; ++k)
    if (pairs[k] >= selfPairs_.size() || pairFrame_[pairs[k]] != frame) frame = -1;
  std::fill(posedLinks_.begin(), posedLinks_.end(), 0);
  for (std::size_t k = 0; k < count; ++k) {
    const auto& links = frame >= 0 ? pairRelativeLinks_[pairs[k]] : pairLinks_[pairs[k]];
    for (std::size_t w = 0; w < links.size(); ++w) posedLinks_[w] |= links[w];
  }
  kinematics_.computeSome(q.data(), poseScratch_.data(), posedLinks_, frame);
  beginLane(poseScratch_.data(), 1, 0);
  posed_ = q;
}

double CheckerState::testPair(std::size_t pair) {
  const std::size_t selfCount = selfPairs_.size();
  const bool self = pair < selfCount;
  int a, b;
  double gap;
  if (self) {
    std::tie(a, b) = selfPairs_[pair];
    for (const int l : {a, b})
      if (!boundPlaced_[static_cast<std::size_t>(l)]) placeBound(l);
    const double c1[3] = {boundX_[static_cast<std::size_t>(a)], boundY_[static_cast<std::size_t>(a)],
                          boundZ_[static_cast<std::size_t>(a)]};
    const double c2[3] = {boundX_[static_cast<std::size_t>(b)], boundY_[static_cast<std::size_t>(b)],
                          boundZ_[static_cast<std::size_t>(b)]};
    gap = sphereSphereGap(c1, 0.0, c2, 0.0) - pairRadiusSum_[pair];
  } else {
    const std::size_t k = pair - selfCount, linkCount = geometricLinks_.size();
    a = geometricLinks_[k % linkCount];
    b = static_cast<int>(k / linkCount);
    if (!boundPlaced_[static_cast<std::size_t>(a)]) placeBound(a);
    const double c[3] = {boundX_[static_cast<std::size_t>(a)], boundY_[static_cast<std::size_t>(a)],
                         boundZ_[static_cast<std::size_t>(a)]};
    gap = sphereGap(obstacles_[static_cast<std::size_t>(b)].part, c, geometricBoundR_[k % linkCount]);
  }
  if (gap > band_) return gap;
  const Outcome outcome = self ? linkPairContact(a, b, gap) : linkObstacleContact(a, static_cast<std::size_t>(b), gap);
  if (outcome == Outcome::Apart) return gap;
  if (outcome == Outcome::Overlapping) return -1.0;
  exact_.kinematics().linkPoses(posed_, exactPoses_);
  ++statistics_.pairsConfirmed;
  const bool collides = self ? exact_.linkPairCollides(exactPoses_, a, b)
                             : exact_.linkObstacleCollides(exactPoses_, a, static_cast<std::size_t>(b));
  return collides ? -1.0 : 0.0;
}

}  // namespace fast

std::size_t PairTests::pairCount() const { return state_->pairCount(); }

void PairTests::pose(const Configuration& q, const std::size_t* pairs, std::size_t count) {
  state_->poseState(q, pairs, count);
}

double PairTests::test(std::size_t pair) { return state_->testPair(pair); }

double PairTests::share(std::size_t pair) const { return state_->pairShare(pair); }

}  // namespace pmdplan
