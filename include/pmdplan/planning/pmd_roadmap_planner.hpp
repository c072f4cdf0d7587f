#pragma once
// The paper's planner (Sect. 5, Algorithm 4): a probabilistic roadmap grown from hand-arm samples
// drawn around the start-goal arm segment, with hands from the PMD subspace (or, for the baseline,
// the whole hand joint box), searched with A* and smoothed. Shaped like an OMPL planner:
// construct, setStartAndGoal, solve, read path() and statistics(), clear.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

#include "pmdplan/planning/pmd_planner_base.hpp"
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

class PmdRoadmapPlanner : public PmdPlannerBase {
 public:
  /// The validators are borrowed and must outlive the planner.
  PmdRoadmapPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                    std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters = {});

  void setProgressCallback(ProgressCallback callback) { progress_ = std::move(callback); }

  /// Checks the space, the parameters and the problem (solve() calls it too). Throws InputError
  /// for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup();
  /// One run from the seed: builds the roadmap from scratch until c_ini and c_goal are joined or a
  /// limit is reached, then finds and smooths the path (A*'s path is unsmoothedPath()).
  PlannerStatus solve();
  /// Drops the roadmap, the path and the statistics.
  void clear();

  const Roadmap& roadmap() const { return roadmap_; }

 private:
  NodeIndex addNode(const Configuration& q, double step, int handDimension);
  std::optional<NodeIndex> forcedNeighbour(double step) const;
  PlannerStatus findPath();
  PlannerStatus endRun(PlannerStatus status);

  ProgressCallback progress_;
  double startGoalDistance_ = 0.0;
  double neighbourThreshold_ = 0.0;

  Roadmap roadmap_;
  NodeIndex startNode_ = 0;
  NodeIndex goalNode_ = 0;
};

}  // namespace pmdplan
