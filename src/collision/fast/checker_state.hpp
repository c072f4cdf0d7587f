#pragma once
// Everything the fast checker (fast_collision_checker.hpp) holds: the task's parts and pairs, the
// per-pair motion weights, and the scratch of its two screens — the scalar one for a single
// configuration (scalar_screen.cpp, over the narrow phase of narrow_phase.cpp) and the lane-vector
// one for a batch (batch_screen.cpp, over the pair kernels of this folder). Private to them.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pmdplan/collision/batched_forward_kinematics.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/fast/screen_result.hpp"
#include "pmdplan/collision/link_part_model.hpp"
#include "pmdplan/collision/simd_level.hpp"

namespace pmdplan::fast {

struct CheckerState {
  static constexpr int kLanes = BatchedForwardKinematics::kLanes;

  /// EnclosuresOverlap: like Uncertain (the exact checker decides), with a mesh's enclosure overlapping the
  /// other side by more than the band, so the exact checker is asked about it first.
  enum class Outcome { Apart, Overlapping, Uncertain, EnclosuresOverlap };
  /// A pair not proven apart: self (two links) or a link and an obstacle.
  struct Flag {
    bool self;
    int a;
    int b;
    Outcome outcome;
  };

  CheckerState(const Task& task, ExactCollisionChecker& exact, double band);

  std::size_t pairCount() const { return selfPairs_.size() + geometricLinks_.size() * obstacles_.size(); }
  double pairShare(std::size_t pair) const {
    return pair < selfPairs_.size() ? pairShare_[pair]
                                    : linkShare_[(pair - selfPairs_.size()) % geometricLinks_.size()];
  }
  void setMotion(const Configuration& from, const Configuration& to);

  // One pair at a time (pair_tests.cpp): forward kinematics of q for the given pairs only, then
  // pair `pair` at that state (PairTests::pose, PairTests::test).
  void poseState(const Configuration& q, const std::size_t* pairs, std::size_t count);
  double testPair(std::size_t pair);
  /// Distance between two spheres' surfaces (negative when they overlap).
  static double sphereSphereGap(const double* a, double ra, const double* b, double rb) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz) - ra - rb;
  }

  // The scalar screen (scalar_screen.cpp): one configuration, lane `lane` of poses laid out with
  // `stride` lanes.
  template <class OnFlag>
  double screenLane(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag,
                    double* pairGaps = nullptr);
  bool decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly, double* safeDisplacement,
              double* pairGaps = nullptr);
  ScreenResult screen(const Configuration& q, bool armOnly);

  // The narrow phase (narrow_phase.cpp): the parts of one lane placed on first use.
  void beginLane(const double* poses, int stride, int lane);
  void placeBound(int link);
  Outcome linkPairContact(int a, int b, double& gap);
  Outcome linkObstacleContact(int link, std::size_t obstacle, double& gap);
  /// The link's parts with their bounding spheres placed (the rest of each part is not yet).
  const ConvexPart* placedBounds(int link);
  /// Part `index` of the link, all of it placed (placedBounds first).
  const ConvexPart& placedPart(int link, std::size_t index);
  /// The exact checker on the pairs in uncertain_ at q: is q free?
  bool confirmUncertain(const Configuration& q);

  // The batch screen (batch_screen.cpp): kLanes configurations at once. With `stopAt`, the lanes
  // are decided in order only until one's verdict is *stopAt: its index is returned and the lanes
  // after it are left undecided. Otherwise (or when none is) returns count.
  int screenBatch(const Configuration* const* configurations, int count, const double* poses, bool* valid, double* safe,
                  double* pairGaps, const bool* stopAt = nullptr);
  // screenBatch's lane-vector stage: fills pairLaneGaps_, laneSafe_ and laneScalar_ in vectors
  // laneWidth(simdLevel_) wide. `tight`: every pair's gap as tight as these tests get it (the
  // caller keeps them, as motion-check certificates), not just tight enough to prove.
  void screenLanes(const double* poses, int count, bool tight);
  template <class V>
  void screenLanesOf(const double* poses, int count, int first, bool tight);
  /// screenLanesOf's obstacle o, of kind K, against the links' (and subtrees') bounds.
  template <ConvexPart::Kind K, class V>
  void screenObstacleOf(std::size_t o, int first, bool tight);

  // Set up once (checker_state.cpp).
  void computeMotionWeights(const RobotModel& model);
  void orderGeometricLinks(const RobotModel& model);
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
  std::vector<double> partLanes_;      ///< the link parts placed, then the obstacles (lane_parts.hpp)
  std::vector<char> partLanesPlaced_;  ///< per link
  std::vector<double> pairLaneGaps_;   ///< per pair (pairCount()): its gap, a lower bound
  std::vector<char> pairNear_;         ///< per pair: its bounds meet in some lane
  std::vector<double> subtreeLanes_;   ///< per geometricLinks_ entry: its subtree's bound radius
  /// Every pair's part pairs (pair p's from pairPartsBegin_[p] to pairPartsBegin_[p + 1]); part
  /// indices into partShapes_ and partLanes_.
  std::vector<ConvexPart> partShapes_;  ///< the link parts (in their links' frames), then the obstacles
  /// The kernel of a part pair (one header each: capsule_capsule.hpp, capsule_box.hpp, ...),
  /// chosen once at setup. A pair's parts are stored in the order of the kernel's name; a box and a
  /// cylinder keep the order of their pair (CylinderBox: the cylinder came first, its axis is tried
  /// first), as do two parts of one kind.
  enum class PartPairKind : std::uint8_t {
    CapsuleCapsule,
    CapsuleBox,
    CapsuleCylinder,
    BoxBox,
    BoxCylinder,
    CylinderBox,
    CylinderCylinder
  };
  static constexpr int kPartPairKinds = 7;
  struct PartPair {
    std::uint32_t indexA, indexB;
    PartPairKind kind;
    double inverseA, inverseB;  ///< capsules: 1 / their cores' squared lengths (0: a point)
  };
  std::vector<PartPair> partPairs_;
  std::vector<std::uint32_t> pairPartsBegin_;
  std::vector<double> partPairGaps_;  ///< per part pair: its gap, a lower bound
  /// The part pairs whose bounding spheres meet, by kind: kind k's from partWorkBegin_[k] on.
  std::vector<std::uint32_t> partWork_;
  std::uint32_t partWorkBegin_[kPartPairKinds] = {};
  double laneSafe_[kLanes] = {};
  std::vector<std::size_t> laneScalar_[kLanes];  ///< per lane: the pairs it tests alone

  std::size_t checks_ = 0;
  FastCheckStatistics statistics_;
};

}  // namespace pmdplan::fast
