#pragma once
// Straight joint-space segments checked at a resolution from SweptDistanceBound, so that no point
// of the robot moves more than `tolerance` between two checked states. Interior states are visited
// in bisection (Van der Corput) order, which finds a collision early on average.
#include <functional>
#include <optional>

#include "pmdplan/collision/collision_report.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"

namespace pmdplan {

struct SegmentInspection {
  bool free = true;
  std::optional<double> firstCollision;  ///< smallest colliding fraction in [0, 1]
  CollisionReport collisions;            ///< pairs at the first colliding state
  long statesChecked = 0;
  long statesNeeded = 0;  ///< intervals + 1: what the tolerance requires, endpoints included
};

class SegmentChecker : public MotionValidator {
 public:
  static constexpr double kDefaultTolerance = 0.001;  ///< metres

  SegmentChecker(StateValidator& states, const RobotModel& model, double tolerance = kDefaultTolerance);

  /// Interior states only (endpoints are the planner's already-valid nodes), early exit.
  bool isValid(const Configuration& from, const Configuration& to) override;
  std::size_t statesChecked() const override { return statesChecked_; }

  double tolerance() const { return tolerance_; }
  const SweptDistanceBound& bound() const { return bound_; }

  /// Every state from `from` to `to`, endpoints included, in order along the segment, stopping at
  /// the first collision and reporting its pairs (for `pmdplan check` and `pmdplan validate`).
  SegmentInspection inspect(ExactCollisionChecker& checker, const Configuration& from, const Configuration& to) const;
  /// The same with another state check: `check(q)` reports the pairs that count at q.
  SegmentInspection inspect(const std::function<CollisionReport(const Configuration&)>& check,
                            const Configuration& from, const Configuration& to) const;

 private:
  StateValidator& states_;
  SweptDistanceBound bound_;
  double tolerance_;
  std::size_t statesChecked_ = 0;
};

}  // namespace pmdplan
