#pragma once
// OMPL's geometric planners on our problems: a RealVectorStateSpace over the normalised joint box
// [0, 1]^n, whose states are checked by our StateValidator and whose motions by our
// MotionValidator (the same checks, at the same tolerance, as the PMD planner), stopped by a
// wall-clock limit. Planner settings are OMPL's defaults. OMPL types stay inside the .cpp.
// OmplPlanner (ompl_planner.hpp) runs it behind the Planner interface.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

struct OmplPlanningResult {
  /// OMPL reported an exact solution (an approximate one is not a solution here).
  bool solved = false;
  /// OMPL's status text ("Exact solution", "Timeout", ...).
  std::string status;
  /// OMPL's status as ours: Solved, InvalidStart, InvalidGoal, else (a timeout, an approximate
  /// solution) TimeLimit.
  PlannerStatus plannerStatus = PlannerStatus::NotRun;
  /// The solution's states (start and goal exactly the given ones); empty unless solved.
  std::vector<Configuration> path;
  /// Seconds of setup() and solve().
  double planningTimeSeconds = 0.0;
  /// States the planner asked the validity checker about (motion ends included).
  std::size_t stateChecks = 0;
  /// MotionValidator::statesChecked() during the run.
  std::size_t motionChecks = 0;
  /// Vertices of the planner's data after solving ("graph states" in OMPL's benchmarks).
  std::size_t graphStates = 0;
};

/// One of OMPL's planners we run.
struct OmplPlannerKind {
  std::string name;  ///< OMPL's: "RRTConnect"
  std::string description;
  /// The same seed gives the same run (PlannerEntry::repeatable).
  bool repeatable = true;
};

/// Every OMPL planner ompl_planning runs, in the order the roster lists them: RRTConnect, PRM,
/// LazyPRM, KPIECE1, BKPIECE1, EST, RRT.
std::vector<OmplPlannerKind> omplPlannerKinds();

/// True for the names of omplPlannerKinds().
bool isOmplPlannerName(const std::string& name);

/// PMD sampling for OMPL's planners (the `@pmd` suffix): every planner's states are drawn by
/// OmplPmdStateSampler (src/bench/ompl_pmd_state_sampler.hpp) from this model and arm region.
struct OmplPmdSampling {
  /// The PMD hand sampler (makeHandSampler of the Synergy mode).
  std::shared_ptr<const HandSampler> hands;
  /// Of these: the PMD box, rho_a, the arm region's growth (connect-arm-growth, connect-round) and
  /// the sequence.
  PlannerSettings parameters;
};

/// One run. Sets OMPL's process-wide seed (ompl::RNG::setSeed), which OMPL honours only before its
/// first random number in a process: call this once per process (pmdplan bench forks a process per
/// run). `seed` must not be 0 (OMPL ignores it). Throws std::invalid_argument for an unknown name.
OmplPlanningResult planWithOmpl(const std::string& plannerName, const PlanningSpace& space, StateValidator& states,
                                MotionValidator& motions, const Configuration& start, const Configuration& goal,
                                double timeLimitSeconds, std::uint64_t seed,
                                const OmplPmdSampling* pmdSampling = nullptr);

}  // namespace pmdplan
