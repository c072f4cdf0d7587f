#pragma once
// The state and motion checks a planner runs on one task, built for a checker kind: the exact
// FCL checker with SegmentChecker, or the fast checker with its batched segment checks. Planners
// (ours and OMPL's) see only StateValidator and MotionValidator, so every planner of a comparison
// gets the same checks at the same tolerance.
#include <memory>

#include "pmdplan/collision/checker_kind.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

class CollisionChecking {
 public:
  /// `task` is kept by reference: it must outlive this object.
  CollisionChecking(const Task& task, CheckerKind kind, double toleranceMetres = SegmentChecker::kDefaultTolerance);
  ~CollisionChecking();
  CollisionChecking(const CollisionChecking&) = delete;
  CollisionChecking& operator=(const CollisionChecking&) = delete;

  CheckerKind kind() const { return kind_; }
  double tolerance() const { return tolerance_; }
  StateValidator& states() { return *states_; }
  MotionValidator& motions() { return *motions_; }
  /// The exact reference checker behind either kind (for reports; the fast kind confirms with it).
  ExactCollisionChecker& exact() { return *exact_; }

 private:
  CheckerKind kind_;
  double tolerance_;
  std::unique_ptr<ExactCollisionChecker> exact_;
  std::unique_ptr<StateValidator> fastStates_;  ///< null for the exact kind
  StateValidator* states_ = nullptr;
  std::unique_ptr<MotionValidator> motions_;
};

}  // namespace pmdplan
