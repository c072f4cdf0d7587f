// The fast checker one pair at a time (pair_tests.hpp): the links a pair needs posed, then its
// bounds, its parts (narrow_phase.hpp) and, within the band, FCL.
#include "pmdplan/collision/fast/pair_tests.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "checker_model.hpp"
#include "checker_scratch.hpp"
#include "narrow_phase.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan {

std::size_t PairTests::pairCount() const { return model_->pairCount(); }

void PairTests::pose(const Configuration& q, const std::size_t* pairs, std::size_t count) {
  const fast::CheckerModel& model = *model_;
  fast::CheckerScratch& scratch = *scratch_;
  if (q.size() != model.dof()) throw std::invalid_argument("configuration size does not match the robot");
  const fast::PairLinks& pairLinks = model.pairLinks();
  const std::size_t selfCount = model.selfPairs().size();
  // Self pairs below one common link are posed relative to it; anything else in the world.
  int frame = count > 0 && pairs[0] < selfCount ? pairLinks.frame[pairs[0]] : -1;
  for (std::size_t k = 1; k < count && frame >= 0; ++k)
    if (pairs[k] >= selfCount || pairLinks.frame[pairs[k]] != frame) frame = -1;
  fast::PairPosing& posing = scratch.posing();
  std::fill(posing.links.begin(), posing.links.end(), 0);
  for (std::size_t k = 0; k < count; ++k) {
    const auto& links = frame >= 0 ? pairLinks.relative[pairs[k]] : pairLinks.world[pairs[k]];
    for (std::size_t w = 0; w < links.size(); ++w) posing.links[w] |= links[w];
  }
  model.kinematics().computeSome(q.data(), scratch.poses(), posing.links, frame);
  fast::beginLane(model, scratch, scratch.poses(), 1, 0);
  posing.state = q;
}

double PairTests::test(std::size_t pair) {
  using fast::Outcome;
  const fast::CheckerModel& model = *model_;
  fast::CheckerScratch& scratch = *scratch_;
  const fast::LaneScratch& lane = scratch.lane();
  const fast::GeometricLinks& geometric = model.geometricLinks();
  const std::size_t selfCount = model.selfPairs().size();
  const bool self = pair < selfCount;
  int a, b;
  double gap;
  if (self) {
    std::tie(a, b) = model.selfPairs().pairs[pair];
    for (const int l : {a, b})
      if (!lane.boundPlaced[static_cast<std::size_t>(l)]) fast::placeBound(model, scratch, l);
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    const double c1[3] = {lane.boundX[ua], lane.boundY[ua], lane.boundZ[ua]};
    const double c2[3] = {lane.boundX[ub], lane.boundY[ub], lane.boundZ[ub]};
    gap = fast::sphereSphereGap(c1, 0.0, c2, 0.0) - model.selfPairs().radiusSum[pair];
  } else {
    const std::size_t k = pair - selfCount, linkCount = geometric.size();
    a = geometric.links[k % linkCount];
    b = static_cast<int>(k / linkCount);
    if (!lane.boundPlaced[static_cast<std::size_t>(a)]) fast::placeBound(model, scratch, a);
    const auto ua = static_cast<std::size_t>(a);
    const double c[3] = {lane.boundX[ua], lane.boundY[ua], lane.boundZ[ua]};
    gap = sphereGap(model.obstacles()[static_cast<std::size_t>(b)].part, c, geometric.boundRadius[k % linkCount]);
  }
  if (gap > model.band()) return gap;
  const Outcome outcome = self ? fast::linkPairContact(model, scratch, a, b, gap)
                               : fast::linkObstacleContact(model, scratch, a, static_cast<std::size_t>(b), gap);
  if (outcome == Outcome::Apart) return gap;
  if (outcome == Outcome::Overlapping) return -1.0;
  const ExactCollisionChecker& exact = scratch.exact();
  exact.kinematics().linkPoses(scratch.posing().state, scratch.exactPoses());
  ++scratch.statistics().pairsConfirmed;
  const bool collides = self ? exact.linkPairCollides(scratch.exactPoses(), a, b)
                             : exact.linkObstacleCollides(scratch.exactPoses(), a, static_cast<std::size_t>(b));
  return collides ? -1.0 : 0.0;
}

double PairTests::share(std::size_t pair) const {
  const fast::MotionShares& shares = scratch_->shares();
  const std::size_t selfCount = model_->selfPairs().size();
  return pair < selfCount ? shares.pair[pair] : shares.link[(pair - selfCount) % model_->geometricLinks().size()];
}

}  // namespace pmdplan
