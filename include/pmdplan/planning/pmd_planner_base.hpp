#pragma once
// What the three PMD planners (PmdRoadmapPlanner, the paper's; LazyPmdPlanner and PmdConnectPlanner,
// ours) share, as OMPL's base::Planner does for its planners: their implementation of the Planner
// interface (planner.hpp) up to setup, solve and clear: the problem (the space, the borrowed
// validators, the hand sampler, the parameters, c_ini and c_goal with the arm sampler along their
// segment), one run's random source and clock, and its results (the path before and after
// smoothing, the statistics). A planner adds its roadmap or trees, setup(), solve() and clear().
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/core/sequences/unit_points.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner.hpp"
#include "pmdplan/planning/planner_run.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

class PmdPlannerBase : public Planner {
 public:
  /// c_ini and c_goal: full configurations within the limits. They need not lie in the PMD subspace.
  void setStartAndGoal(Configuration start, Configuration goal) override;

  /// The smoothed path (c_ini first, c_goal last); empty unless solved.
  const std::vector<Configuration>& path() const override { return path_; }
  /// The path the search found, before smoothing.
  const std::vector<Configuration>& unsmoothedPath() const { return unsmoothedPath_; }
  const PlanningStatistics& statistics() const override { return statistics_; }
  const PlanningSpace& space() const { return space_; }
  const PlannerSettings& parameters() const { return parameters_; }
  const HandSampler& handSampler() const { return *handSampler_; }

 protected:
  /// The validators are borrowed and must outlive the planner; `name` heads its error messages.
  PmdPlannerBase(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                 std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters, std::string name);

  /// Checks the parameters, the space and the problem and places the arm sampler on the segment.
  /// Throws InputError for bad parameters, std::invalid_argument for a malformed space or problem.
  void setupProblem();
  /// Drops the path and the statistics.
  void clearResults();
  /// Starts the sample sequences again from the seed and starts the clock (after the planner's
  /// clear()). `segmentPointDimension`: 1 for a planner that draws points of the start-goal segment
  /// from the sequence (PointStream::SegmentPoint), else 0.
  void beginRun(int segmentPointDimension = 0);
  /// Checks c_ini, then c_goal, counting each check: the status to end with if one collides.
  std::optional<PlannerStatus> checkStartAndGoalStates();
  /// Closes the statistics with the status, the clock and the roadmap's size.
  PlannerStatus finishRun(PlannerStatus status, std::size_t roadmapNodes, std::size_t roadmapEdges);

  PlanningSpace space_;
  StateValidator& stateValidator_;
  MotionValidator& motionValidator_;
  std::unique_ptr<HandSampler> handSampler_;
  PlannerSettings parameters_;

  Configuration start_;
  Configuration goal_;
  std::optional<ArmSegmentSampler> armSampler_;

  UnitPoints points_;
  std::vector<Configuration> path_;
  std::vector<Configuration> unsmoothedPath_;
  PlanningStatistics statistics_;
  PlannerRun run_;

 private:
  std::string name_;
};

}  // namespace pmdplan
