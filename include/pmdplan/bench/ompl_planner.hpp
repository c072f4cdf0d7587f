#pragma once
// OMPL's geometric planners behind our Planner interface (planning/planner.hpp), so that `plan`,
// `bench` and Python run them through the one service (planning/task_planning.hpp) as they run
// ours. A solve() is one planWithOmpl run (ompl_planning.hpp) in the normalised joint box, its
// states drawn by OMPL's sampler or, for `@pmd`, by PMD sampling; the path then gets our planners'
// smoothing (Sect. 5.3, planning/path_smoothing.hpp) with the same motion checks, if the settings
// ask for it, not bounded by the time limit (as the benchmarks have always smoothed OMPL's paths).
// Of the settings it honours the seed (not 0, which OMPL ignores), the time limit, smoothing and,
// for `@pmd`, what PMD sampling uses (OmplPmdSampling). A colliding start or goal is reported
// before OMPL runs (InvalidStart, InvalidGoal), as ours report it.
// Seeds: OMPL's seed is process-wide (ompl::RNG::setSeed) and honoured only before its first random
// number in a process, so the same seed repeats a run in a fresh process only (`bench` forks one
// per run; a `plan` is one process).
// Statistics: samples and stateChecks count the states OMPL's planner asked about, roadmapNodes its
// graph's vertices, motionChecks the planning's and the smoothing's motion checks.
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner.hpp"
#include "pmdplan/planning/planner_registry.hpp"

namespace pmdplan {

class OmplPlanner final : public Planner {
 public:
  /// `omplName`: one of omplPlannerKinds() (std::invalid_argument otherwise). `pmdSampling` needs
  /// the context's synergy model (makeHandSampler's errors otherwise).
  OmplPlanner(const PlannerContext& context, std::string omplName, bool pmdSampling);

  /// "ompl:RRTConnect", "ompl:RRTConnect@pmd".
  std::string name() const override;
  void setStartAndGoal(Configuration start, Configuration goal) override;
  /// Throws InputError for bad settings (a seed of 0 too), std::invalid_argument for a malformed
  /// space or problem.
  void setup() override;
  PlannerStatus solve() override;
  void clear() override;
  const std::vector<Configuration>& path() const override { return path_; }
  const PlanningStatistics& statistics() const override { return statistics_; }

 private:
  PlannerStatus finish(PlannerStatus status);

  PlanningSpace space_;
  StateValidator& states_;
  MotionValidator& motions_;
  PlannerSettings settings_;
  std::string omplName_;
  std::shared_ptr<const HandSampler> pmdHands_;  ///< set for PMD sampling
  Configuration start_;
  Configuration goal_;
  std::vector<Configuration> path_;
  PlanningStatistics statistics_;
};

/// The registry lines of OMPL's planners: "ompl:<Name>" for each of omplPlannerKinds(), then each
/// again with PMD sampling, "ompl:<Name>@pmd".
std::vector<PlannerEntry> omplPlannerEntries();

}  // namespace pmdplan
