#pragma once
// The paper's planner (Sect. 5, Algorithm 4): a probabilistic roadmap grown from hand-arm samples
// drawn around the start-goal arm segment, with hands from the PMD subspace (or, for the baseline,
// the whole hand joint box), searched with A* and smoothed. Shaped like an OMPL planner:
// construct, setStartAndGoal, solve, read path() and statistics(), clear.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/core/random_source.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner_parameters.hpp"
#include "pmdplan/planning/planner_run.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"
#include "pmdplan/planning/roadmap.hpp"
#include "pmdplan/planning/search_range.hpp"

namespace pmdplan {

/// A snapshot for a progress display, given before each hypercube is sampled.
struct PlannerProgress {
  std::size_t sweep = 0;       ///< k of Algorithm 4
  double armHalfSize = 0.0;    ///< rho_a of this sweep
  std::size_t hypercube = 0;   ///< index i in the Van der Corput order, 0 .. hypercubes-1
  std::size_t hypercubes = 0;  ///< STEPS + 1
  SearchRange searchRange;
  std::size_t samples = 0;  ///< hand-arm draws so far
  std::size_t roadmapNodes = 0;
  std::size_t components = 0;
  double elapsedSeconds = 0.0;
};
/// Must not touch the planner; it only observes.
using ProgressCallback = std::function<void(const PlannerProgress&)>;

class PmdRoadmapPlanner {
 public:
  /// The validators are borrowed and must outlive the planner.
  PmdRoadmapPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                    std::unique_ptr<HandSampler> handSampler, PlannerParameters parameters = {});
  PmdRoadmapPlanner(const PmdRoadmapPlanner&) = delete;
  PmdRoadmapPlanner& operator=(const PmdRoadmapPlanner&) = delete;

  /// c_ini and c_goal: full configurations within the limits. They need not lie in the PMD subspace.
  void setStartAndGoal(Configuration start, Configuration goal);
  void setProgressCallback(ProgressCallback callback) { progress_ = std::move(callback); }

  /// Checks the space, the parameters and the problem (solve() calls it too). Throws InputError
  /// for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup();
  /// One run from the seed: builds the roadmap from scratch until c_ini and c_goal are joined or a
  /// limit is reached, then finds and smooths the path.
  PlannerStatus solve();
  /// Drops the roadmap, the path and the statistics.
  void clear();

  /// The smoothed path (c_ini first, c_goal last); empty unless solved.
  const std::vector<Configuration>& path() const { return path_; }
  /// The path A* found, before smoothing.
  const std::vector<Configuration>& unsmoothedPath() const { return unsmoothedPath_; }
  const PlanningStatistics& statistics() const { return statistics_; }
  const Roadmap& roadmap() const { return roadmap_; }
  const PlanningSpace& space() const { return space_; }
  const PlannerParameters& parameters() const { return parameters_; }
  const HandSampler& handSampler() const { return *handSampler_; }

 private:
  NodeIndex addNode(const Configuration& q, double step, int handDimension);
  std::optional<NodeIndex> forcedNeighbour(double step) const;
  PlannerStatus findPath();
  void beginRun();
  PlannerStatus endRun(PlannerStatus status);

  PlanningSpace space_;
  StateValidator& stateValidator_;
  MotionValidator& motionValidator_;
  std::unique_ptr<HandSampler> handSampler_;
  PlannerParameters parameters_;
  ProgressCallback progress_;

  Configuration start_;
  Configuration goal_;
  std::optional<ArmSegmentSampler> armSampler_;
  double startGoalDistance_ = 0.0;
  double neighbourThreshold_ = 0.0;

  RandomSource random_;
  Roadmap roadmap_;
  NodeIndex startNode_ = 0;
  NodeIndex goalNode_ = 0;
  std::vector<Configuration> path_;
  std::vector<Configuration> unsmoothedPath_;
  PlanningStatistics statistics_;
  PlannerRun run_;
};

}  // namespace pmdplan
