#pragma once
// The paper's planner (PmdRoadmapPlanner, Algorithm 4) as an OMPL planner, so OMPL code and
// OMPL's benchmark tools (ompl::tools::Benchmark, ompl_benchmark_statistics) run it like their own.
//
// The problem is OMPL's: a RealVectorStateSpace with one dimension per joint of `space` (same
// order); coordinate j maps affinely from the state space's bounds onto joint j's limits (the
// normalised box of makeOmplTaskSpace, or the joint limits themselves). States are checked with the
// space information's validity checker, segments with its motion validator. The start is the
// problem's first start state, the goal one sample of its (sampleable) goal region.
//
// Every row of plannerSettingTable() (planning/planner_setting_table.hpp) is an OMPL parameter,
// named like the Python PlannerSettings' property (rho_a, neighbours, neighbour_threshold, ...,
// connect_probes) and taking the command line's text ("0.01", "linear", "on"); the rows of the
// other PMD planners (lazy_*, connect_*) are accepted and unused here. The termination condition
// bounds the run besides time_limit (infinite by default): it is tested before every hypercube.
// seed 0 (the default) draws each run's seed from an ompl::RNG, so ompl::RNG::setSeed makes runs
// repeatable and repeated runs differ, as with OMPL's planners; any other seed repeats that run.
//
// Deviation: OMPL has no arm-only self-collision check, so Algorithm 1's SELFCOLLISION(c^a)
// filter passes every arm sample here and the full check of the hand-arm sample decides alone
// (the same paths; more full checks). motion_checks in the statistics counts checkMotion calls.
#include <ompl/base/Planner.h>
#include <ompl/util/RandomNumbers.h>

#include <memory>
#include <optional>

#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

class PmdRoadmapPlanner;

class OmplPmdPlanner : public ompl::base::Planner {
 public:
  /// `synergies` is required for the Synergy mode (std::invalid_argument otherwise). Named
  /// "PMD" (Synergy) or "PMDFull" (FullSpace) unless `name` is given.
  OmplPmdPlanner(const ompl::base::SpaceInformationPtr& si, PlanningSpace space, HandSamplingMode mode,
                 std::shared_ptr<const SynergyModel> synergies, const std::string& name = "");
  ~OmplPmdPlanner() override;

  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  void clear() override;
  void setup() override;
  /// The last run's roadmap: start and goal tagged as such, every edge both ways with its length.
  /// The states stay valid until the next solve(), getPlannerData() or clear().
  void getPlannerData(ompl::base::PlannerData& data) const override;

  PlannerSettings& parameters() { return parameters_; }
  const PlannerSettings& parameters() const { return parameters_; }
  /// Of the last run (also what getPlannerData's properties report).
  const PlanningStatistics& statistics() const { return statistics_; }

 private:
  void declareParameters();
  Configuration configurationOf(const ompl::base::State* state) const;
  void setState(const Configuration& q, ompl::base::State* state) const;
  void releaseDataStates() const;

  PlanningSpace space_;
  HandSamplingMode mode_;
  std::shared_ptr<const SynergyModel> synergies_;
  PlannerSettings parameters_;
  ompl::RNG rng_;
  std::unique_ptr<PmdRoadmapPlanner> planner_;  ///< of the last run, kept for getPlannerData
  PlanningStatistics statistics_;
  mutable std::vector<ompl::base::State*> dataStates_;  ///< the states getPlannerData handed out
  /// Per dimension: the state space's lower bound and its extent.
  std::vector<double> boundsLow_, boundsExtent_;
};

}  // namespace pmdplan
