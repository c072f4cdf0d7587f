#include "pmdplan/collision/collision_checking.hpp"

#include <stdexcept>

namespace pmdplan {

CollisionChecking::CollisionChecking(const Task& task, CheckerKind kind, double toleranceMetres)
    : kind_(kind), tolerance_(toleranceMetres), exact_(std::make_unique<ExactCollisionChecker>(task)) {
  if (kind == CheckerKind::Fast) throw std::logic_error("the fast checker is not built yet");
  states_ = exact_.get();
  motions_ = std::make_unique<SegmentChecker>(*states_, *task.robot, toleranceMetres);
}

CollisionChecking::~CollisionChecking() = default;

}  // namespace pmdplan
