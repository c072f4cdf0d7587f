#pragma once
// The fast checker: the exact checker's answers at a fraction of its cost.
// Forward kinematics runs for several configurations at once (BatchedForwardKinematics), and so do
// checkBatch's geometric stages (fast_batch_screen.cpp, on lane vectors). Every link is a few
// convex parts equal to its URDF primitives, or enclosing its meshes (link_part_model.hpp), inside
// a bounding sphere. For
// one configuration, a broad phase tests the bounding spheres of the same enabled self pairs as the exact
// checker and of every link against the obstacles, in branch-free passes; the pairs whose spheres
// meet go to the narrow phase, part against part (partContact: closed form for two capsules, GJK
// otherwise), which proves them apart (with a lower bound on the gap) or overlapping by more than
// `band`. Only a pair within `band` of touching, or a mesh not proven apart, is handed to FCL
// (ExactCollisionChecker::linkPairCollides / linkObstacleCollides) — so every answer equals the
// exact checker's while FCL runs on almost no checks. Pairs that no joint moves (links fixed to
// the base, static obstacles) are decided once, by FCL.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pmdplan/collision/batched_forward_kinematics.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/link_part_model.hpp"
#include "pmdplan/collision/simd_level.hpp"
#include "pmdplan/collision/state_validator.hpp"

namespace pmdplan {

/// What the geometric stages alone say about one configuration (no FCL).
struct ScreenResult {
  /// Pairs proven to overlap by more than the band (FCL agrees: they collide).
  std::vector<std::pair<int, int>> overlappingSelf;              ///< link indices
  std::vector<std::pair<int, std::size_t>> overlappingObstacle;  ///< (link, obstacle index)
  /// Pairs neither proven apart nor overlapping: FCL decides them.
  std::vector<std::pair<int, int>> uncertainSelf;
  std::vector<std::pair<int, std::size_t>> uncertainObstacle;
  /// When every pair is proven apart: how far (m) every point of the robot may move with all of
  /// them staying apart (a lower bound from the gaps, halved for two moving links); else 0.
  double safeDisplacement = 0.0;
  bool provenFree() const {
    return overlappingSelf.empty() && overlappingObstacle.empty() && uncertainSelf.empty() && uncertainObstacle.empty();
  }
};

/// How the checks of a FastCollisionChecker were decided.
struct FastCheckStatistics {
  std::size_t provenFree = 0;          ///< every pair proven apart by the geometric stages
  std::size_t provenColliding = 0;     ///< a pair proven overlapping (FCL not asked)
  std::size_t confirmedFree = 0;       ///< uncertain pairs, all found free by FCL
  std::size_t confirmedColliding = 0;  ///< an uncertain pair found colliding by FCL
  std::size_t pairsConfirmed = 0;      ///< FCL pair tests run
};

class FastCollisionChecker : public StateValidator {
 public:
  static constexpr int kLanes = BatchedForwardKinematics::kLanes;
  /// Parts closer than this (m) to touching, or interpenetrating by less, are left to FCL: far
  /// above FCL's own tolerances (about 1e-6 m) and far below anything a plan could notice.
  static constexpr double kDefaultBand = 2e-5;

  /// `exact` must be built on the same task and outlive this checker; its check count is not
  /// touched (confirmations are pair tests).
  FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, double band = kDefaultBand);

  /// The instruction set of checkBatch's geometric stages, lane vectors laneWidth(level) wide: the
  /// widest the CPU has by default; a narrower one can be chosen (tests compare them). Throws
  /// std::invalid_argument for a level the CPU cannot run.
  SimdLevel simdLevel() const { return simdLevel_; }
  void setSimdLevel(SimdLevel level);

  bool isValid(const Configuration& q) override;
  bool isArmValid(const Configuration& q) override;
  std::size_t checkCount() const override { return checks_; }

  /// Up to kLanes configurations at once (forward kinematics batched): valid[i] as isValid, and
  /// safe[i] > 0 when the geometric stages alone proved it free: ScreenResult's safeDisplacement,
  /// or after setMotion the fraction of that segment by which the robot may move from this state
  /// with every pair staying apart. With `pairGaps` (count x pairCount() values), the gap of every
  /// pair of every valid configuration is written there too (0 for a pair only FCL could clear).
  /// Counts `count` checks.
  void checkBatch(const Configuration* const* configurations, int count, bool* valid, double* safe,
                  double* pairGaps = nullptr);

  // One pair at a time, for motion checks that follow each pair along a segment (FastSegmentChecker).
  // Pairs are numbered: the self pairs with a moving link, then every moving link with geometry
  // against every obstacle.
  std::size_t pairCount() const { return selfPairs_.size() + geometricLinks_.size() * obstacles_.size(); }
  /// Forward kinematics of q for testPair of the given pairs only (not counted as a check).
  void poseState(const Configuration& q, const std::size_t* pairs, std::size_t count);
  /// Pair `pair` at the posed state: a lower bound on its gap (m), 0 if only FCL could clear it
  /// (and FCL did), -1 if it collides.
  double testPair(std::size_t pair);
  /// After setMotion: 1 / (how far, in m, the pair's two sides may approach each other over the
  /// whole segment), so gap * pairShare is the fraction of the segment it stays apart for.
  double pairShare(std::size_t pair) const {
    return pair < selfPairs_.size() ? pairShare_[pair]
                                    : linkShare_[(pair - selfPairs_.size()) % geometricLinks_.size()];
  }

  /// Measures checkBatch's safe values in fractions of the straight segment from -> to, with a
  /// displacement bound per link pair (only the joints between the two links count) and per
  /// link (its own chain), rather than one bound for the whole robot.
  void setMotion(const Configuration& from, const Configuration& to);

  /// The geometric stages alone, every pair not proven apart listed. Not counted as a check.
  ScreenResult screen(const Configuration& q, bool armOnly = false);

  const FastCheckStatistics& statistics() const { return statistics_; }
  const std::vector<LinkParts>& links() const { return links_; }
  const ExactCollisionChecker& exact() const { return exact_; }
  double band() const { return band_; }

 private:
  /// EnclosuresOverlap: like Uncertain (FCL decides), with a mesh's enclosure overlapping the
  /// other side by more than the band, so FCL is asked about it first.
  enum class Outcome { Apart, Overlapping, Uncertain, EnclosuresOverlap };
  /// A pair not proven apart: self (two links) or a link and an obstacle.
  struct Flag {
    bool self;
    int a;
    int b;
    Outcome outcome;
  };

  template <class OnFlag>
  double screenLane(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag,
                    double* pairGaps = nullptr);
  void beginLane(const double* poses, int stride, int lane);
  void placeBound(int link);
  Outcome linkPairContact(int a, int b, double& gap);
  Outcome linkObstacleContact(int link, std::size_t obstacle, double& gap);
  /// The link's parts with their bounding spheres placed (the rest of each part is not yet).
  const ConvexPart* placedBounds(int link);
  /// Part `index` of the link, all of it placed (placedBounds first).
  const ConvexPart& placedPart(int link, std::size_t index);
  void computeMotionWeights(const RobotModel& model);
  void orderGeometricLinks(const RobotModel& model);
  bool decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly, double* safeDisplacement,
              double* pairGaps = nullptr);
  /// FCL on the pairs in uncertain_ at q: is q free?
  bool confirmUncertain(const Configuration& q);
  /// checkBatch's geometric stages, all lanes at once (fast_batch_screen.cpp).
  void screenBatch(const Configuration* const* configurations, int count, const double* poses, bool* valid,
                   double* safe, double* pairGaps);
  // screenBatch's lane-vector stage (fast_batch_screen.cpp): fills pairLaneGaps_, laneSafe_ and
  // laneScalar_ in vectors laneWidth(simdLevel_) wide. `tight`: every pair's gap as tight as these tests get
  // it (the caller keeps them, as motion-check certificates), not just tight enough to prove.
  void screenLanes(const double* poses, int count, bool tight);
  template <class V>
  void screenLanesOf(const double* poses, int count, int first, bool tight);
  static void screenAvx512(FastCollisionChecker& checker, const double* poses, int count, bool tight);
  static void screenAvx2(FastCollisionChecker& checker, const double* poses, int count, bool tight);
  static void screenSse2(FastCollisionChecker& checker, const double* poses, int count, bool tight);
  /// Sizes the lane scratch, spreads the obstacles over the lanes, lists the part pairs.
  void prepareLanes();

  ExactCollisionChecker& exact_;
  double band_;
  SimdLevel simdLevel_ = widestSimdLevel();
  std::vector<LinkParts> links_;
  std::vector<ObstaclePart> obstacles_;
  BatchedForwardKinematics kinematics_;
  std::vector<char> moving_;         ///< per link: does any joint move it?
  std::vector<int> boundLinks_;      ///< every link with geometry
  std::vector<int> geometricLinks_;  ///< moving links with geometry, depth first
  std::vector<double> geometricBoundR_;
  /// Per geometricLinks_ entry: the entry of its nearest ancestor in the list (-1: none), and the
  /// end of the run of its descendants (the entries after it up to there).
  std::vector<int> geometricParent_, geometricSubtreeEnd_;

  // Self pairs with a moving link, in the exact checker's order, as plain arrays for the broad phase.
  std::vector<std::pair<int, int>> selfPairs_;
  std::vector<char> pairIsArm_;
  std::vector<int> pairA_, pairB_;
  std::vector<double> pairRadiusSum_;
  /// Gap multipliers for the safe value: 1 / (links that move) by default (metres), or
  /// 1 / (relative displacement over the segment) after setMotion (fractions of the segment).
  std::vector<double> pairShare_, linkShare_;
  std::vector<double> pairWeights_, linkWeights_;             ///< metres per unit of each active joint
  std::vector<BatchedForwardKinematics::LinkSet> pairLinks_;  ///< per pair: the links its world poses need
  /// Per self pair: the deepest link above both, and the links below it that their poses relative
  /// to it need (the pair's distance does not depend on the joints above).
  std::vector<int> pairFrame_;
  std::vector<BatchedForwardKinematics::LinkSet> pairRelativeLinks_;
  BatchedForwardKinematics::LinkSet posedLinks_;
  // Pairs of links no joint moves that collide (decided once); any makes every check fail.
  std::vector<std::pair<int, int>> staticSelfCollisions_, staticArmSelfCollisions_;
  std::vector<std::pair<int, std::size_t>> staticEnvironmentCollisions_;

  // Scratch for one lane: link bound centres; parts placed in the world on first use.
  const double* lanePoses_ = nullptr;
  int laneStride_ = 1, lane_ = 0;
  std::vector<double> boundX_, boundY_, boundZ_;              ///< by link
  std::vector<double> geometricX_, geometricY_, geometricZ_;  ///< by geometricLinks_ entry
  std::vector<double> pairGaps_, pairDx_, pairDy_, pairDz_, obstacleGaps_;
  std::vector<int> partOffset_;
  std::vector<ConvexPart> worldParts_;
  std::vector<char> placed_, boundPlaced_, partPlaced_;
  std::vector<double> linkPoses_;  ///< placed links' poses, 12 values each
  std::vector<double> poseScratch_;
  Configuration posed_;  ///< the state poseState last posed

  std::vector<Flag> uncertain_;
  LinkPoses exactPoses_;

  // Scratch of screenBatch: numbers as [item][value][lane].
  std::vector<double> boundLanes_;     ///< link bound centres
  std::vector<double> partLanes_;      ///< the link parts placed, then the obstacles (fast_batch_screen.cpp)
  std::vector<char> partLanesPlaced_;  ///< per link
  std::vector<double> pairLaneGaps_;   ///< per pair (pairCount()): its gap, a lower bound
  std::vector<char> pairNear_;         ///< per pair: its bounds meet in some lane
  std::vector<double> subtreeLanes_;   ///< per geometricLinks_ entry: its subtree's bound radius
  /// Every pair's part pairs (pair p's from pairPartsBegin_[p] to pairPartsBegin_[p + 1]); part
  /// indices into partShapes_ and partLanes_.
  std::vector<ConvexPart> partShapes_;  ///< the link parts (in their links' frames), then the obstacles
  struct PartPair {
    std::uint32_t indexA, indexB;
    bool capsules;              ///< both capsules: their exact distance, else separating axes
    double inverseA, inverseB;  ///< capsules: 1 / their cores' squared lengths (0: a point)
  };
  std::vector<PartPair> partPairs_;
  std::vector<std::uint32_t> pairPartsBegin_;
  std::vector<double> partPairGaps_;                   ///< per part pair: its gap, a lower bound
  std::vector<std::uint32_t> capsuleWork_, faceWork_;  ///< the part pairs whose bounding spheres meet
  double laneSafe_[kLanes] = {};
  std::vector<std::size_t> laneScalar_[kLanes];  ///< per lane: the pairs it tests alone

  std::size_t checks_ = 0;
  FastCheckStatistics statistics_;
};

}  // namespace pmdplan
