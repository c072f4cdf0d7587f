#pragma once
// What one planner run did (the paper's Table 2, plus path length and collision checks).
#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace pmdplan {

enum class PlannerStatus {
  NotRun,
  Solved,
  SampleLimit,   ///< N samples (or N arm trials) drawn without joining c_ini and c_goal
  TimeLimit,     ///< the wall-clock limit stopped the roadmap construction
  InvalidStart,  ///< c_ini is in collision
  InvalidGoal,   ///< c_goal is in collision
};

/// "not_run", "solved", "sample_limit", "time_limit", "invalid_start", "invalid_goal".
std::string plannerStatusName(PlannerStatus status);
/// Inverse of plannerStatusName; std::nullopt for anything else.
std::optional<PlannerStatus> parsePlannerStatus(const std::string& name);

struct PlanningStatistics {
  PlannerStatus status = PlannerStatus::NotRun;
  /// Seconds from the start of solve() to the end of A* (roadmap construction and search).
  double planningTime = 0.0;
  /// Seconds spent smoothing the path.
  double smoothingTime = 0.0;
  /// rho_a of the last sweep (Table 2's "final neighbouring threshold").
  double finalArmHalfSize = 0.0;
  /// Sweeps over the hypercubes (values of k in Algorithm 4).
  std::size_t sweeps = 0;
  /// Largest number of hand trials (passes of the j×h loops) one hypercube needed before it gave a
  /// free sample.
  std::size_t maxTrials = 0;
  /// Samples as Table 2 and Table 4 count them: hand-arm configurations drawn and checked (passes
  /// of the h loop; the authors' code counts one per hand draw).
  std::size_t samples = 0;
  /// Arm configurations tried (passes of the j loop, whether or not the arm came free).
  std::size_t armTrials = 0;
  /// Nodes (c_ini and c_goal included) and edges of the roadmap.
  std::size_t roadmapNodes = 0;
  std::size_t roadmapEdges = 0;
  /// Sampled nodes by the active hand dimension that produced them (2 = thumb base + 1 PMD, ...).
  std::map<int, std::size_t> nodesByHandDimension;
  /// Nodes of the final path and of the path A* returned before smoothing (0 if not solved).
  std::size_t pathNodes = 0;
  std::size_t pathNodesBeforeSmoothing = 0;
  /// Lengths in normalised joint space (0 if not solved).
  double pathLength = 0.0;
  double pathLengthBeforeSmoothing = 0.0;
  /// Configurations the planner itself checked: start, goal, arm draws (isArmValid) and hand-arm
  /// draws (isValid). Counted by the planner, not read from StateValidator::checkCount(), because a
  /// MotionValidator may check its states through the same StateValidator.
  std::size_t stateChecks = 0;
  /// MotionValidator::statesChecked() during the run (roadmap edges and smoothing).
  std::size_t motionChecks = 0;
  /// stateChecks + motionChecks.
  std::size_t collisionChecks() const { return stateChecks + motionChecks; }

  bool solved() const { return status == PlannerStatus::Solved; }
};

}  // namespace pmdplan
