#include "pmdplan/collision/collision_checking.hpp"

#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "pmdplan/collision/fast_segment_checker.hpp"

namespace pmdplan {

CollisionChecking::CollisionChecking(const Task& task, CheckerKind kind, double toleranceMetres)
    : kind_(kind), tolerance_(toleranceMetres), exact_(std::make_unique<ExactCollisionChecker>(task)) {
  if (kind == CheckerKind::Fast) {
    auto fast = std::make_unique<FastCollisionChecker>(task, *exact_);
    motions_ = std::make_unique<FastSegmentChecker>(*fast, *task.robot, toleranceMetres);
    fastStates_ = std::move(fast);
    states_ = fastStates_.get();
  } else {
    states_ = exact_.get();
    motions_ = std::make_unique<SegmentChecker>(*states_, *task.robot, toleranceMetres);
  }
}

CollisionChecking::~CollisionChecking() = default;

}  // namespace pmdplan
