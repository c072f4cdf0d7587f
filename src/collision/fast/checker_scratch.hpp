#pragma once
// What one fast checker writes while it checks (fast_collision_checker.hpp), next to the task's
// immutable CheckerModel (checker_model.hpp): the poses of the configurations being checked, the
// parts placed for them, the screens' lane buffers and gaps, the pairs left to the exact checker,
// the shares of the motion being checked, the checker's statistics, and the exact checker it
// confirms pairs with (whose own scratch makes it one checker's too). One per checker (or thread);
// sized for its model once.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "checker_model.hpp"
#include "pair_outcome.hpp"
#include "pmdplan/collision/fast/screen_result.hpp"

namespace pmdplan::fast {

/// One configuration's narrow phase (narrow_phase.hpp): a lane of posed links, their bound centres,
/// and their parts placed in the world on first use.
struct LaneScratch {
  const double* poses = nullptr;  ///< the lane's poses: [(link * 12 + value) * stride + lane]
  int stride = 1, lane = 0;
  std::vector<double> boundX, boundY, boundZ;  ///< by link
  std::vector<ConvexPart> worldParts;          ///< by part (CheckerModel::partOffset)
  std::vector<char> placed, boundPlaced;       ///< by link
  std::vector<char> partPlaced;                ///< by part
  std::vector<double> linkPoses;               ///< placed links' poses, 12 values each
};

/// The scalar screen's broad phase (scalar_screen.cpp), in passes over plain arrays.
struct ScalarScratch {
  std::vector<double> geometricX, geometricY, geometricZ;  ///< by GeometricLinks entry
  std::vector<double> pairGaps, pairDx, pairDy, pairDz;    ///< by self pair
  std::vector<double> obstacleGaps;                        ///< by obstacle, then GeometricLinks entry
};

/// The batch screen's lanes (batch_screen.cpp): numbers as [item][value][lane].
struct BatchScratch {
  static constexpr int kLanes = BatchedForwardKinematics::kLanes;
  std::vector<double> boundLanes;     ///< link bound centres
  std::vector<double> partLanes;      ///< the link parts placed, then the obstacles (lane_parts.hpp)
  std::vector<char> partLanesPlaced;  ///< per link
  std::vector<double> pairLaneGaps;   ///< per pair (CheckerModel::pairCount): its gap, a lower bound
  std::vector<char> pairNear;         ///< per pair: its bounds meet in some lane
  std::vector<double> subtreeLanes;   ///< per GeometricLinks entry: its subtree's bound radius
  std::vector<double> partPairGaps;   ///< per part pair (PartPairTable): its gap, a lower bound
  /// The part pairs whose bounding spheres meet, by kind: kind k's from PartPairTable::kindBegin[k].
  std::vector<std::uint32_t> partWork;
  double laneSafe[kLanes] = {};
  std::vector<std::size_t> laneScalar[kLanes];  ///< per lane: the pairs it tests alone
};

/// The gap multipliers for the safe value (MotionWeights): per self pair and per GeometricLinks
/// entry, by default in metres, after FastCollisionChecker::setMotion in fractions of that motion.
struct MotionShares {
  std::vector<double> pair, link;
};

/// The state PairTests last posed, and the links it posed.
struct PairPosing {
  BatchedForwardKinematics::LinkSet links;
  Configuration state;
};

class CheckerScratch {
 public:
  /// `exact` must fit the model (CheckerModel::fits) and outlive the scratch.
  CheckerScratch(const CheckerModel& model, const ExactCollisionChecker& exact);

  const ExactCollisionChecker& exact() const { return *exact_; }

  LaneScratch& lane() { return lane_; }
  ScalarScratch& scalar() { return scalar_; }
  BatchScratch& batch() { return batch_; }
  MotionShares& shares() { return shares_; }
  const MotionShares& shares() const { return shares_; }
  PairPosing& posing() { return posing_; }
  /// Forward kinematics' output: a batch's poses, or one configuration's.
  double* poses() { return poses_.data(); }
  /// The pairs the geometric stages left to the exact checker, and the poses it reads.
  std::vector<Flag>& uncertain() { return uncertain_; }
  LinkPoses& exactPoses() { return exactPoses_; }
  FastCheckStatistics& statistics() { return statistics_; }
  const FastCheckStatistics& statistics() const { return statistics_; }

 private:
  const ExactCollisionChecker* exact_;
  LaneScratch lane_;
  ScalarScratch scalar_;
  BatchScratch batch_;
  MotionShares shares_;
  PairPosing posing_;
  std::vector<double> poses_;
  std::vector<Flag> uncertain_;
  LinkPoses exactPoses_;
  FastCheckStatistics statistics_;
};

}  // namespace pmdplan::fast
