#pragma once
// An independent check of a planned path with the exact checker: every point within the limits
// and free, the ends equal to the task's start and goal, every segment free at the tolerance.
#include <string>
#include <vector>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/segment_checker.hpp"

namespace pmdplan {

struct PathValidation {
  bool valid = true;
  long statesChecked = 0;
  /// Human-readable problems, e.g. "segment 3 (2 -> 3): collides at 41.2 %: index_distal_link - goal_can".
  std::vector<std::string> problems;
  /// Colliding pairs found (points and segments), each once.
  CollisionReport collisions;
};

PathValidation validatePath(ExactCollisionChecker& checker, const SegmentChecker& segments,
                            const std::vector<Configuration>& path, const Configuration& start, const Configuration& goal);

}  // namespace pmdplan
