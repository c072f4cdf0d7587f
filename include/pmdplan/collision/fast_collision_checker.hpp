#pragma once
// The fast checker: a conservative sphere stage, then the exact FCL checker on what it flags only.
// Stage 1 covers every link by spheres that enclose its primitives (LinkSphereModel) and tests
// the same enabled self pairs as the exact checker (link, then primitive bounding spheres exit
// early) and every link against the obstacles (SphereEnvironment). Spheres apart means the real
// geometry is apart, so "free" is final; a flagged link pair or link-obstacle pair is decided by
// ExactCollisionChecker::linkPairCollides / linkObstacleCollides on the exact checker's own poses.
// The answer therefore equals ExactCollisionChecker::isValid / isArmValid on every configuration.
// Pairs that no joint moves (links fixed to the base, static obstacles) are decided once, exactly.
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "pmdplan/collision/batched_forward_kinematics.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/link_sphere_model.hpp"
#include "pmdplan/collision/sphere_environment.hpp"
#include "pmdplan/collision/state_validator.hpp"

namespace pmdplan {

struct FastCheckerParameters {
  SphereCoverParameters spheres;
};

/// What the sphere stage alone says about one configuration.
struct SphereStageVerdict {
  std::vector<std::pair<int, int>> selfPairs;                  ///< flagged link pairs (link indices)
  std::vector<std::pair<int, std::size_t>> obstaclePairs;      ///< flagged (link, obstacle index)
  /// When nothing is flagged: how far (m) every point of the robot may move with all tested pairs
  /// staying apart (a lower bound: sphere gaps, halved for two moving links); 0 when flagged.
  /// After FastCollisionChecker::setMotion: the fraction of that segment instead.
  double safeDisplacement = 0.0;
  bool free() const { return selfPairs.empty() && obstaclePairs.empty(); }
};

/// How the checks of a FastCollisionChecker were decided.
struct FastCheckStatistics {
  std::size_t sphereFree = 0;      ///< free by the sphere stage alone
  std::size_t confirmedFree = 0;   ///< flagged, found free by FCL on the flagged pairs
  std::size_t colliding = 0;       ///< flagged and colliding
  std::size_t pairsConfirmed = 0;  ///< FCL pair tests run
};

class FastCollisionChecker : public StateValidator {
public:
  static constexpr int kLanes = BatchedForwardKinematics::kLanes;

  /// `exact` must be built on the same task and outlive this checker; its check count is not
  /// touched (confirmations are pair tests).
  FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, const FastCheckerParameters& parameters = {});

  bool isValid(const Configuration& q) override;
  bool isArmValid(const Configuration& q) override;
  std::size_t checkCount() const override { return checks_; }

  /// Up to kLanes configurations at once (forward kinematics batched): valid[i] as isValid, and
  /// safe[i] > 0 when the sphere stage alone found it free: as SphereStageVerdict's
  /// safeDisplacement, or after setMotion the fraction of that segment by which the robot may
  /// move from this state with every tested pair staying apart. Counts `count` checks.
  void checkBatch(const Configuration* const* configurations, int count, bool* valid, double* safe);

  /// Measures checkBatch's safe values in fractions of the straight segment from -> to, with a
  /// displacement bound per link pair (only the joints between the two links count) and per
  /// link (its own chain), rather than one bound for the whole robot.
  void setMotion(const Configuration& from, const Configuration& to);

  /// The sphere stage alone, every flagged pair listed (no FCL). Not counted as a check.
  SphereStageVerdict sphereStage(const Configuration& q, bool armOnly = false);

  const FastCheckStatistics& statistics() const { return statistics_; }
  const LinkSphereModel& spheres() const { return spheres_; }
  const ExactCollisionChecker& exact() const { return exact_; }

private:
  template <class OnFlag>
  double runStage(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag);
  void computeMotionWeights(const RobotModel& model);
  void placeLink(int link, const double* poses, int stride, int lane);
  /// Places the spheres of one primitive of a placed link; returns their offset in world*_.
  int placeGroup(int link, int group);
  /// The world box of a box group of a placed link (turned on first use).
  const SolidPrimitive& placedBox(int link, int group);
  double groupPairGap(int a, int ga, int b, int gb, const double* boundB);
  bool decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly, double* safeDisplacement);

  ExactCollisionChecker& exact_;
  LinkSphereModel spheres_;
  SphereEnvironment environment_;
  BatchedForwardKinematics kinematics_;
  std::vector<char> moving_;  ///< per link: does any joint move it?
  std::vector<std::pair<int, int>> movingSelfPairs_;
  std::vector<char> pairIsArm_;  ///< per movingSelfPairs_ entry
  std::vector<int> pairA_, pairB_;  ///< the same pairs as plain arrays for the bound pass
  std::vector<double> pairRadiusSum_, pairGaps_, pairDx_, pairDy_, pairDz_;
  /// Gap multipliers for the safe value: 1 / (links that move) by default (metres), or
  /// 1 / (relative displacement over the segment) after setMotion (fractions of the segment).
  std::vector<double> pairShare_, linkShare_;
  std::vector<double> pairWeights_, linkWeights_;  ///< metres per unit of each active joint
  std::vector<int> boundLinks_;  ///< every link with geometry
  std::vector<double> movingBoundX_, movingBoundY_, movingBoundZ_, movingBoundR_, obstacleGaps_;  ///< by geometricLinks_ entry
  std::vector<int> geometricLinks_;  ///< moving links with geometry
  // Pairs of links no joint moves that collide (decided once); any makes every check fail.
  std::vector<std::pair<int, int>> staticSelfCollisions_, staticArmSelfCollisions_;
  std::vector<std::pair<int, std::size_t>> staticEnvironmentCollisions_;

  // Scratch for one lane: world bounds and spheres, placed lazily per link.
  std::vector<double> boundX_, boundY_, boundZ_;
  std::vector<int> sphereOffset_, groupOffset_;
  std::vector<double> worldX_, worldY_, worldZ_, worldR_;
  std::vector<double> groupX_, groupY_, groupZ_, groupR_;
  std::vector<SolidPrimitive> worldBoxes_;  ///< box groups, by group index
  std::vector<Capsule> worldCapsules_;      ///< capsule groups, by group index
  std::vector<char> placed_, groupPlaced_, boxPlaced_;
  std::vector<double> linkPoses_;  ///< placed links' poses (12 values each)
  std::vector<double> poseScratch_;
  LinkPoses exactPoses_;

  std::size_t checks_ = 0;
  FastCheckStatistics statistics_;
};

}  // namespace pmdplan
