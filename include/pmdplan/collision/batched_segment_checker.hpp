#pragma once
// The fast checker's motion validator: the same discrete states as SegmentChecker (the state count
// SweptDistanceBound needs for the tolerance, interior states in the same Van der Corput order),
// several states per batch of FastCollisionChecker::checkBatch. The answer equals SegmentChecker's
// on the exact checker: a segment is blocked exactly when one of those states collides.
// Skipping: where the sphere stage finds a state free, every pair it tested has a gap g; along the
// segment the two links of a pair approach each other at most at a rate r (metres per segment,
// from the joints between them only: FastCollisionChecker::setMotion), so every state less than
// min(g / r) of the segment away is free too and is not evaluated. The answer is unchanged; only
// the work is. statesChecked() counts the states evaluated (sphere stage run, FCL where flagged),
// statesSkipped() the interior states proven free without evaluation.
#include <cstddef>
#include <vector>

#include "pmdplan/collision/fast_collision_checker.hpp"
#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"

namespace pmdplan {

class BatchedSegmentChecker : public MotionValidator {
public:
  /// `states` must outlive this checker. tolerance in metres.
  BatchedSegmentChecker(FastCollisionChecker& states, const RobotModel& model, double tolerance);

  bool isValid(const Configuration& from, const Configuration& to) override;
  std::size_t statesChecked() const override { return statesChecked_; }
  std::size_t statesSkipped() const { return statesSkipped_; }

  double tolerance() const { return tolerance_; }
  const SweptDistanceBound& bound() const { return bound_; }

private:
  FastCollisionChecker& states_;
  SweptDistanceBound bound_;
  double tolerance_;
  std::size_t statesChecked_ = 0;
  std::size_t statesSkipped_ = 0;
  std::vector<long> order_;
  std::vector<char> covered_;
};

/// Interior indices 1 .. intervals-1 in SegmentChecker's breadth-first bisection order.
void bisectionOrder(long intervals, std::vector<long>& order);

}  // namespace pmdplan
