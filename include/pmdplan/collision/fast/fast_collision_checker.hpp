#pragma once
// The fast checker: the exact checker's answers at a fraction of its cost.
// Forward kinematics runs for several configurations at once (BatchedForwardKinematics), and so do
// checkBatch's geometric stages (src/collision/fast/batch_screen.cpp, on lane vectors). Every link
// is a few convex parts equal to its URDF primitives, or enclosing its meshes (link_part_model.hpp),
// inside a bounding sphere. For one configuration, a broad phase tests the bounding spheres of the
// same enabled self pairs as the exact checker and of every link against the obstacles, in
// branch-free passes; the pairs whose spheres meet go to the narrow phase, part against part
// (partContact: closed form for two capsules, GJK otherwise), which proves them apart (with a lower
// bound on the gap) or overlapping by more than `band`. Only a pair within `band` of touching, or a
// mesh not proven apart, is handed to the exact checker (ExactCollisionChecker::linkPairCollides /
// linkObstacleCollides) — so every answer equals the exact checker's while it runs on almost no
// checks. Pairs that no joint moves (links fixed to the base, static obstacles) are decided once,
// by the exact checker. The task's parts and pairs form an immutable model built once
// (src/collision/fast/checker_model.hpp), which checkers may share; each checker writes only its
// own scratch (checker_scratch.hpp); the stages are functions of the two (docs/architecture.md).
#include <cstddef>
#include <memory>
#include <vector>

#include "pmdplan/collision/batched_forward_kinematics.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/fast/pair_tests.hpp"
#include "pmdplan/collision/fast/screen_result.hpp"
#include "pmdplan/collision/link_part_model.hpp"
#include "pmdplan/collision/simd_level.hpp"
#include "pmdplan/collision/state_validator.hpp"

namespace pmdplan {
namespace fast {
class CheckerModel;
class CheckerScratch;
}  // namespace fast

class FastCollisionChecker : public StateValidator {
 public:
  static constexpr int kLanes = BatchedForwardKinematics::kLanes;
  /// Parts closer than this (m) to touching, or interpenetrating by less, are left to the exact
  /// checker: far above its numerical margins (about 1e-9 m) and far below anything a plan could
  /// notice.
  static constexpr double kDefaultBand = 2e-5;

  /// `exact` must be built on the same task and outlive this checker; its check count is not
  /// touched (confirmations are pair tests).
  FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, double band = kDefaultBand);
  /// A checker on another's model (model(): the same task and band, nothing rebuilt), confirming
  /// with `exact` (built on the same Task object as the model's; it must outlive this checker),
  /// with its own scratch, statistics, check count, motion and SIMD level: with an exact checker
  /// each, checkers sharing one model may run in parallel threads. Throws std::invalid_argument
  /// for another task's exact checker or no model.
  FastCollisionChecker(std::shared_ptr<const fast::CheckerModel> model, ExactCollisionChecker& exact);
  ~FastCollisionChecker() override;
  FastCollisionChecker(const FastCollisionChecker&) = delete;
  FastCollisionChecker& operator=(const FastCollisionChecker&) = delete;

  /// The instruction set of checkBatch's geometric stages, lane vectors laneWidth(level) wide: the
  /// widest the CPU has by default; a narrower one can be chosen (tests compare them). Throws
  /// std::invalid_argument for a level the CPU cannot run.
  SimdLevel simdLevel() const;
  void setSimdLevel(SimdLevel level);

  bool isValid(const Configuration& q) override;
  bool isArmValid(const Configuration& q) override;
  std::size_t checkCount() const override;
  /// kLanes configurations at a time through the batch screen; within a batch the lanes the lane
  /// vectors leave open are decided one by one only up to the one found.
  int firstWithValidity(const Configuration* const* configurations, int count, bool valid) override;

  /// Up to kLanes configurations at once (forward kinematics batched): valid[i] as isValid, and
  /// safe[i] > 0 when the geometric stages alone proved it free: ScreenResult's safeDisplacement,
  /// or after setMotion the fraction of that segment by which the robot may move from this state
  /// with every pair staying apart. With `pairGaps` (count x pairCount() values), the gap of every
  /// pair of every valid configuration is written there too (0 for a pair only the exact checker could clear).
  /// Counts `count` checks.
  void checkBatch(const Configuration* const* configurations, int count, bool* valid, double* safe,
                  double* pairGaps = nullptr);

  /// The pairs one at a time (pair_tests.hpp).
  PairTests& pairs() { return pairs_; }
  std::size_t pairCount() const { return pairs_.pairCount(); }

  /// Measures checkBatch's safe values and the pair shares in fractions of the straight segment
  /// from -> to, with a displacement bound per link pair (only the joints between the two links
  /// count) and per link (its own chain), rather than one bound for the whole robot.
  void setMotion(const Configuration& from, const Configuration& to);

  /// The geometric stages alone, every pair not proven apart listed. Not counted as a check.
  ScreenResult screen(const Configuration& q, bool armOnly = false);

  const FastCheckStatistics& statistics() const;
  const std::vector<LinkParts>& links() const;
  const ExactCollisionChecker& exact() const;
  double band() const;
  /// The task's parts, pairs and weights, built once and never changed after: share it with
  /// another checker through the constructor above.
  std::shared_ptr<const fast::CheckerModel> model() const { return model_; }

 private:
  std::shared_ptr<const fast::CheckerModel> model_;
  std::unique_ptr<fast::CheckerScratch> scratch_;
  SimdLevel simdLevel_;
  std::size_t checks_ = 0;
  PairTests pairs_;
};

}  // namespace pmdplan
