#pragma once
// The grasp rule of docs/grasp_goals.md as the one service everything that judges a task asks:
// `plan`, `validate`, `check`, `bench`, `view` (the viewer data) and the Python module. For a task
// and a path's phases it decides
//   - per state, which colliding pairs are collisions and which are allowed grasp contact (a hand
//     link with the target, only while the hand closes),
//   - which link-obstacle pairs a clearance is measured over in each phase,
//   - whether a path is valid (the path file's phases: where the closing phase starts),
//   - whether `plan` takes the task's start and goal, and if not, why (naming the pairs).
// The pre-grasp a grasp goal needs is the planning layer's (planning/grasp_approach.hpp).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/collision_report.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_contact.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// The phase a state of a path is judged in. A path without phases is all approach.
enum class PathPhase {
  Approach,  ///< every pair counts, the target included
  Closing,   ///< hand-target contact is allowed (grasp contact); every other pair counts
};

/// A path's phases as its file gives them: the closing phase runs from point `closingFrom` (the
/// pre-grasp) to the last point; nullopt: no closing phase.
struct PathPhases {
  std::optional<std::size_t> closingFrom;

  /// Segment i (point i to point i + 1).
  PathPhase segment(std::size_t i) const {
    return closingFrom && i >= *closingFrom ? PathPhase::Closing : PathPhase::Approach;
  }
  /// Point i: a point that ends an approach segment is judged as approach (the pre-grasp too).
  PathPhase point(std::size_t i) const {
    return closingFrom && i > *closingFrom ? PathPhase::Closing : PathPhase::Approach;
  }
};

/// The colliding pairs at one state, as the rule sorts them.
struct StateContacts {
  CollisionReport collisions;  ///< the pairs that count: collisions
  CollisionReport allowed;     ///< hand-target pairs the closing phase allows: grasp contact
  bool free() const { return collisions.free(); }
};

/// Why `plan` will not take a task: the task file's field it names and its message.
struct PlanRefusal {
  std::string field;      ///< "start", "goal" or "pregrasp"
  std::string reason;     ///< plan's message, the pairs and the rule named
  CollisionReport pairs;  ///< the pairs that make it refuse (empty when the reason is not a contact)

  /// Throws InputError(task file, field, reason): plan's exit 2.
  [[noreturn]] void raise(const Task& task) const;
};

enum class GoalContact {
  Free,          ///< touches nothing: planned directly
  GraspsTarget,  ///< only hand links touch, and only the target: approach, then closing
  Refused,       ///< touches something else (or the task has no target)
};

struct GoalContactReport {
  GoalContact contact = GoalContact::Free;
  CollisionReport pairs;               ///< the hand-target pairs (GraspsTarget) or the pairs the rule forbids (Refused)
  std::optional<PlanRefusal> refusal;  ///< set when Refused
};

class GraspRule {
 public:
  /// Keeps `task` by reference. Never throws: a task without a target, or a robot without a palm
  /// link, has no grasp contact (everything counts), and asking for it where it is needed throws.
  explicit GraspRule(const Task& task);

  const Task& task() const { return task_; }
  /// The hand-target part. Throws InputError as GraspContactRule's constructor does (no target,
  /// no palm link).
  const GraspContactRule& contact() const;

  /// Whether a colliding (or near) pair counts in `phase`: everything but grasp contact.
  bool counts(const CollisionPair& pair, PathPhase phase) const;
  /// The pairs colliding at `q`, sorted into collisions and grasp contact.
  StateContacts judgeState(ExactCollisionChecker& checker, const Configuration& q, PathPhase phase) const;
  /// The pairs that count at `q` (judgeState's collisions), for segment inspection.
  CollisionReport collisions(ExactCollisionChecker& checker, const Configuration& q, PathPhase phase) const;

  /// `plan`'s verdict on the start: refused when it is in collision.
  std::optional<PlanRefusal> startRefusal(ExactCollisionChecker& checker) const;
  /// `plan`'s verdict on the goal's contacts (docs/grasp_goals.md, "When it applies"). Whether a
  /// grasp goal's pre-grasp serves is decided by planning/grasp_approach.hpp.
  GoalContactReport judgeGoal(ExactCollisionChecker& checker) const;

  /// The independent check of a path (path_validation.hpp) with its phases: the approach with
  /// every pair counting, the closing with grasp contact allowed; a closing phase in a task
  /// without a target makes the path invalid.
  PathValidation validatePath(ExactCollisionChecker& checker, const SegmentChecker& segments,
                              const std::vector<Configuration>& path, const PathPhases& phases) const;

 private:
  const Task& task_;
  std::optional<GraspContactRule> contact_;  ///< with a target and a palm link
};

}  // namespace pmdplan
