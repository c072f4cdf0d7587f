#pragma once
// The paper's planner (Sect. 5, Algorithm 4): a probabilistic roadmap grown from hand-arm samples
// drawn around the start-goal arm segment, with hands from the PMD subspace (or, for the baseline,
// the whole hand joint box), searched with A* and smoothed. A Planner (planner.hpp), registered as
// `pmd` and, with the full-space hand sampler, `full` (planner_registry.hpp): construct,
// setStartAndGoal, solve, read path() and statistics(), clear. The only planner that reports
// progress (planner_progress.hpp).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "pmdplan/planning/pmd_planner_base.hpp"
#include "pmdplan/planning/roadmap.hpp"
#include "pmdplan/planning/search_range.hpp"

namespace pmdplan {

class PmdRoadmapPlanner : public PmdPlannerBase {
 public:
  /// The validators are borrowed and must outlive the planner.
  PmdRoadmapPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                    std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters = {});

  /// "pmd", or "full" with the full-space hand sampler.
  std::string name() const override { return handSampler().name(); }
  void setProgressCallback(ProgressCallback callback) override { progress_ = std::move(callback); }

  /// Checks the space, the parameters and the problem (solve() calls it too). Throws InputError
  /// for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup() override;
  /// One run from the seed: builds the roadmap from scratch until c_ini and c_goal are joined or a
  /// limit is reached, then finds and smooths the path (A*'s path is unsmoothedPath()).
  PlannerStatus solve() override;
  /// Drops the roadmap, the path and the statistics.
  void clear() override;

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
