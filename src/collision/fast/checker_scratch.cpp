#include "checker_scratch.hpp"

#include <algorithm>
#include <cstddef>

#include "lane_parts.hpp"

namespace pmdplan::fast {

CheckerScratch::CheckerScratch(const CheckerModel& model, const ExactCollisionChecker& exact) : exact_(&exact) {
  constexpr int kValues = BatchedForwardKinematics::kPoseValues;
  const std::size_t links = model.links().size(), parts = model.linkPartCount();
  const std::size_t geometric = model.geometricLinks().size(), selfPairs = model.selfPairs().size();
  const std::size_t pairs = model.pairCount(), partPairs = model.partPairs().pairs.size();

  lane_.boundX.assign(links, 0.0), lane_.boundY = lane_.boundZ = lane_.boundX;
  lane_.worldParts.resize(parts);
  lane_.placed.assign(links, 0);
  lane_.boundPlaced.assign(links, 0);
  lane_.partPlaced.assign(parts, 0);
  lane_.linkPoses.assign(links * kValues, 0.0);

  scalar_.geometricX.assign(geometric, 0.0), scalar_.geometricY = scalar_.geometricZ = scalar_.geometricX;
  scalar_.pairGaps.assign(selfPairs, 0.0);
  scalar_.pairDx = scalar_.pairDy = scalar_.pairDz = scalar_.pairGaps;
  scalar_.obstacleGaps.assign(geometric * model.obstacles().size(), 0.0);

  batch_.boundLanes.assign(links * 3 * L, 0.0);
  // The link parts are placed per batch; the obstacles' never change.
  const std::vector<double>& obstacleLanes = model.partPairs().obstacleLanes;
  batch_.partLanes.assign(parts * kPartValues * L + obstacleLanes.size(), 0.0);
  std::copy(obstacleLanes.begin(), obstacleLanes.end(),
            batch_.partLanes.end() - static_cast<std::ptrdiff_t>(obstacleLanes.size()));
  batch_.partLanesPlaced.assign(links, 0);
  batch_.pairLaneGaps.assign(pairs * L, 0.0);
  batch_.pairNear.assign(pairs, 0);
  batch_.subtreeLanes.assign(geometric * L, 0.0);
  batch_.partPairGaps.assign(partPairs * L, 0.0);
  batch_.partWork.assign(partPairs, 0);

  model.motionWeights().defaultShares(shares_.pair, shares_.link);
  posing_.links = model.kinematics().emptyLinkSet();
  poses_.resize(model.kinematics().batchPoseSize());
}

}  // namespace pmdplan::fast
