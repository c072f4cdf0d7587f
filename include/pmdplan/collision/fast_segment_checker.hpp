#pragma once
// The fast checker's motion validator. It decides the same discrete states as SegmentChecker (the
// state count SweptDistanceBound needs for the tolerance, state i at from + (to - from) * i / n)
// and gives the same answer: a segment is blocked exactly when one of them collides. It does far
// less work to get there:
//  1. Coarse pass: the first Van der Corput (bisection) states, several per batch of
//     FastCollisionChecker::checkBatch, catch most blocked segments at once.
//  2. Sweep: every pair (two links, or a link and an obstacle) is followed along the segment on
//     its own. A pair found g apart at state i cannot close that gap before the states its two
//     sides need to approach by g (at most `PairTests::share` of the segment per metre, from the joints
//     between them: FastCollisionChecker::setMotion), so it is tested again only there. A state
//     is posed only when some pair's certificate runs out at it, and only those pairs are tested;
//     the coarse states' gaps certify pairs around them too.
// statesChecked() counts the states posed (coarse and swept), statesSkipped() the interior states
// proven free for every pair without being posed.
#include <cstddef>
#include <vector>

#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"

namespace pmdplan {

class FastSegmentChecker : public MotionValidator {
 public:
  /// Bisection states of the coarse pass (at most; state 1 comes on top): the first four levels.
  static constexpr long kCoarseStates = 15;

  /// `states` must outlive this checker. tolerance in metres.
  FastSegmentChecker(FastCollisionChecker& states, const RobotModel& model, double tolerance);

  bool isValid(const Configuration& from, const Configuration& to) override;
  std::size_t statesChecked() const override { return statesChecked_; }
  std::size_t statesSkipped() const { return statesSkipped_; }

  double tolerance() const { return tolerance_; }
  const SweptDistanceBound& bound() const { return bound_; }

 private:
  /// States within a certificate of a gap found at one state: every state less than
  /// gap * share * n states away (a relative allowance for the rounding of interpolated states).
  static long reach(double gap, double share, long n);

  FastCollisionChecker& states_;
  SweptDistanceBound bound_;
  double tolerance_;
  std::size_t statesChecked_ = 0;
  std::size_t statesSkipped_ = 0;
  std::vector<long> order_;
  std::vector<double> coarseGaps_;              ///< per coarse state, per pair
  std::vector<int> bucketHead_, nextInBucket_;  ///< pairs by the state they must be tested at
  std::vector<std::size_t> testing_;
  Configuration state_, batch_[FastCollisionChecker::kLanes];
  std::vector<std::pair<std::size_t, long>> covered_;  ///< (pair, last state a coarse state covers)
  std::vector<std::pair<long, long>> byPosition_;      ///< coarse states: (state, coarse index), sorted
};

/// Interior indices 1 .. intervals-1 in SegmentChecker's breadth-first bisection order (the
/// first `limit` of them).
void bisectionOrder(long intervals, std::vector<long>& order, std::size_t limit = static_cast<std::size_t>(-1));

}  // namespace pmdplan
