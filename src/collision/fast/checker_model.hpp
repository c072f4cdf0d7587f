#pragma once
// The fast checker's model of one task (fast_collision_checker.hpp): the robot's links and the
// obstacles as convex parts, the pairs the screens test, the links each pair's poses need, the
// per-pair motion weights, the pairs decided once, and the batch screen's part pairs. Built once
// per task and const after, so several checkers (each with its own CheckerScratch,
// checker_scratch.hpp, and exact checker) may share one, in one thread or several. The screens are functions of (const
// CheckerModel&, CheckerScratch&): scalar_screen.hpp, batch_screen.hpp, narrow_phase.hpp, pair_tests.cpp.
#include <cstddef>
#include <utility>
#include <vector>

#include "motion_weights.hpp"
#include "part_pair_table.hpp"
#include "pmdplan/collision/batched_forward_kinematics.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/link_part_model.hpp"

namespace pmdplan::fast {

/// The moving links with geometry in depth-first order, so that every link's geometric
/// descendants follow it in one run (the batch screen tests a whole subtree against an obstacle
/// first). Indexed by entry, not by link.
struct GeometricLinks {
  std::vector<int> links;           ///< the link of each entry
  std::vector<double> boundRadius;  ///< its bounding sphere's radius
  /// The entry of its nearest ancestor in the list (-1: none), and the end of the run of its
  /// descendants (the entries after it up to there).
  std::vector<int> parent, subtreeEnd;
  std::size_t size() const { return links.size(); }
};

/// The self pairs with a moving link, in the exact checker's order, as plain arrays for the broad
/// phase. The pairs are numbered: these first, then every geometric link against every obstacle
/// (obstacle-major), the order of FastCollisionChecker::checkBatch's pairGaps.
struct SelfPairs {
  std::vector<std::pair<int, int>> pairs;
  std::vector<char> isArm;  ///< both links belong to the arm
  std::vector<int> a, b;
  std::vector<double> radiusSum;  ///< the two links' bounding radii added
  std::size_t size() const { return pairs.size(); }
};

/// What the poses of each pair need (pair_tests.cpp poses only those links).
struct PairLinks {
  std::vector<BatchedForwardKinematics::LinkSet> world;  ///< per pair: the links its world poses need
  /// Per self pair: the deepest link above both, and the links below it that their poses relative
  /// to it need (the pair's distance does not depend on the joints above).
  std::vector<int> frame;
  std::vector<BatchedForwardKinematics::LinkSet> relative;
};

/// Pairs no joint moves that collide, decided once by the exact checker (their poses never
/// change): any of them makes every check fail.
struct StaticCollisions {
  std::vector<std::pair<int, int>> self, armSelf;
  std::vector<std::pair<int, std::size_t>> environment;
  bool any(bool armOnly) const { return armOnly ? !armSelf.empty() : !(self.empty() && environment.empty()); }
};

class CheckerModel {
 public:
  /// Asks `exact`, built on the same task, which self pairs to test and decides the pairs no joint
  /// moves with it; throws std::invalid_argument if it belongs to another task, or if the band is
  /// not positive.
  CheckerModel(const Task& task, const ExactCollisionChecker& exact, double band);
  CheckerModel(const CheckerModel&) = delete;
  CheckerModel& operator=(const CheckerModel&) = delete;

  /// Could `exact` confirm this model's pairs: built on the same task object as the exact checker
  /// the model was built with?
  bool fits(const ExactCollisionChecker& exact) const { return &exact.task() == task_; }
  /// Parts closer than this to touching are left to the exact checker.
  double band() const { return band_; }
  const BatchedForwardKinematics& kinematics() const { return kinematics_; }
  int dof() const { return kinematics_.dof(); }

  /// Indexed like RobotModel::links(); empty for links without geometry.
  const std::vector<LinkParts>& links() const { return links_; }
  const std::vector<ObstaclePart>& obstacles() const { return obstacles_; }
  /// Per link: does any joint move it?
  const std::vector<char>& moving() const { return moving_; }
  /// Every link with geometry.
  const std::vector<int>& boundLinks() const { return boundLinks_; }
  /// Per link: the index of its first part among every link's parts (the part tables' order).
  const std::vector<int>& partOffset() const { return partOffset_; }
  /// Every link's parts together.
  std::size_t linkPartCount() const { return linkPartCount_; }

  const GeometricLinks& geometricLinks() const { return geometric_; }
  const SelfPairs& selfPairs() const { return selfPairs_; }
  /// Self pairs, then every geometric link against every obstacle.
  std::size_t pairCount() const { return selfPairs_.size() + geometric_.size() * obstacles_.size(); }
  const PairLinks& pairLinks() const { return pairLinks_; }
  const MotionWeights& motionWeights() const { return weights_; }
  const StaticCollisions& staticCollisions() const { return static_; }
  const PartPairTable& partPairs() const { return partPairs_; }

 private:
  const Task* task_;  ///< the exact checker's task, to recognise it (never read)
  double band_;
  std::vector<LinkParts> links_;
  std::vector<ObstaclePart> obstacles_;
  BatchedForwardKinematics kinematics_;
  std::vector<char> moving_;
  std::vector<int> boundLinks_, partOffset_;
  std::size_t linkPartCount_ = 0;
  GeometricLinks geometric_;
  SelfPairs selfPairs_;
  PairLinks pairLinks_;
  MotionWeights weights_;
  StaticCollisions static_;
  PartPairTable partPairs_;
};

}  // namespace pmdplan::fast
