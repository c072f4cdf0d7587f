#pragma once
// The interface every planner implements, shaped like OMPL's ompl::base::Planner: given a start and
// a goal, setup() checks the problem and the settings, solve() runs once from the settings' seed
// and returns its status, path() and statistics() hold the run's results until clear() or the next
// solve(). Ours (PmdRoadmapPlanner, LazyPmdPlanner, PmdConnectPlanner) implement it through
// PmdPlannerBase; OMPL's planners through OmplPlanner (src/bench/). planner_registry.hpp makes
// them by name; tests/bench/planner_contract_test.cpp holds every one of them to this contract.
#include <string>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planner_progress.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

class Planner {
 public:
  Planner() = default;
  Planner(const Planner&) = delete;
  Planner& operator=(const Planner&) = delete;
  virtual ~Planner() = default;

  /// The name the registry knows it by ("pmd", "pmd-lazy", "ompl:RRTConnect", ...).
  virtual std::string name() const = 0;

  /// c_ini and c_goal: full configurations within the joint limits.
  virtual void setStartAndGoal(Configuration start, Configuration goal) = 0;
  /// Checks the settings and the problem (solve() calls it too). Throws InputError for bad
  /// settings, std::invalid_argument for a malformed space or problem (no start and goal, a start
  /// or goal of the wrong size or outside the limits).
  virtual void setup() = 0;
  /// One run from the settings' seed, from scratch: the same seed gives the same path (a time
  /// limit that stops a run aside). Solved, SampleLimit or TimeLimit; InvalidStart (InvalidGoal)
  /// when c_ini (c_goal) is in collision.
  virtual PlannerStatus solve() = 0;
  /// Drops the last run's data structures, path and statistics.
  virtual void clear() = 0;

  /// The solved run's path, c_ini first and c_goal last (smoothed if the settings ask); empty
  /// unless solved.
  virtual const std::vector<Configuration>& path() const = 0;
  virtual const PlanningStatistics& statistics() const = 0;

  /// Observes the run (planner_progress.hpp); planners that do not report ignore it.
  virtual void setProgressCallback(ProgressCallback /*callback*/) {}
};

}  // namespace pmdplan
