#pragma once
// An independent check of a planned path with the exact checker: every point within the limits
// and free, the ends equal to the task's start and goal, every segment free at the tolerance. A
// grasp path's closing phase is checked with the grasp rule's contact part (grasp_contact.hpp).
// Against a task, with the path file's phases, paths are judged through GraspRule::validatePath
// (grasp_rule.hpp), which every command, the Python module, the benchmarks and the viewer use.
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_contact.hpp"
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

/// The closing phase of a grasp path: the segments from point `from` (the pre-grasp) to the end,
/// where `rule` allows hand-target contact.
struct ClosingPhase {
  std::size_t from = 0;
  const GraspContactRule* rule = nullptr;
};

/// The most states one path validation checks, counted before it starts (the sum over the
/// segments of SweptDistanceBound::intervals + 1): 4·10⁵ states take 7–9 s with the exact
/// checker on can_on_table, t_in_clutter or cans_in_shelf (17–22 µs each, docs/robustness.md).
inline constexpr long kMaxValidationStates = 400'000;

/// The states validating `path` needs at the checker's tolerance (each segment's intervals + 1).
/// Throws InputError (field "points") beyond kMaxValidationStates, naming the count and the limit.
long checkValidationWork(const SegmentChecker& segments, const std::vector<Configuration>& path);

/// Before `closing->from` (or everywhere without it) every pair counts. A path's problems name the
/// segment, its phase and the pairs at its first colliding state. Throws InputError when the path
/// needs more than kMaxValidationStates states (checkValidationWork, before any check), and
/// StopRequested (core/stop_request.hpp) at the next state when the caller asks to stop.
PathValidation validatePath(ExactCollisionChecker& checker, const SegmentChecker& segments,
                            const std::vector<Configuration>& path, const Configuration& start,
                            const Configuration& goal, std::optional<ClosingPhase> closing = {});

}  // namespace pmdplan
