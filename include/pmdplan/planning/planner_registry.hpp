#pragma once
// Planners by name, as OMPL makes planners with a PlannerAllocator: what any planner is built from
// (PlannerContext, OMPL's SpaceInformation plus our settings), one registry line per planner
// (PlannerEntry: its name, how to make it), and the registry of ours (ourPlanners(): pmd, full,
// pmd-lazy, pmd-connect). OMPL's planners join them one layer up, where OMPL is linked
// (bench/planner_roster.hpp: plannerRoster(), the names every front end accepts).
// Adding a planner of ours: its file (a Planner, planner.hpp) and one line in ourPlanners()
// (src/planning/planner_registry.cpp); the contract suite (tests/bench/planner_contract_test.cpp)
// then runs it like every other.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/planner.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// What a planner is made from. The validators and the synergy model are borrowed: they must
/// outlive the planner.
struct PlannerContext {
  PlanningSpace space;
  StateValidator& states;
  MotionValidator& motions;
  PlannerSettings settings;
  /// The PMD model, for planners that sample hands from it (PlannerEntry::usesSynergies).
  const SynergyModel* synergies = nullptr;
};

/// Makes a planner; throws InputError for a synergy model that does not fit the space's hand,
/// std::invalid_argument for a missing one.
using PlannerAllocator = std::function<std::unique_ptr<Planner>(const PlannerContext&)>;

/// Which settings a planner honours.
enum class PlannerFamily {
  PmdRoadmap,  ///< ours: every field of PlannerSettings that names it (planner_settings.hpp)
  Ompl,        ///< OMPL's (bench/ompl_planner.hpp): the seed, the time limit, smoothing, PMD sampling's
};

/// One registry line.
struct PlannerEntry {
  std::string name;  ///< as the command line and Python name it: "pmd", "ompl:RRTConnect@pmd"
  std::string description;
  PlannerAllocator allocate;
  /// Whose defaults the planner starts from (PlannerSettings::defaultsFor).
  HandSamplingMode mode = HandSamplingMode::Synergy;
  /// Needs PlannerContext::synergies.
  bool usesSynergies = true;
  PlannerFamily family = PlannerFamily::PmdRoadmap;
  /// The same seed gives the same run (a time limit that stops it aside). False for OMPL's PRM,
  /// whose roadmap grows in a second thread: its runs depend on the threads' timing.
  bool repeatable = true;
};

class PlannerRegistry {
 public:
  /// Throws std::invalid_argument for a name given twice or an entry without an allocator.
  explicit PlannerRegistry(std::vector<PlannerEntry> entries);

  /// In the order help texts and error messages list them.
  const std::vector<PlannerEntry>& entries() const { return entries_; }
  /// The entry of a name, or nullptr.
  const PlannerEntry* find(const std::string& name) const;
  /// The entry of a name; throws std::invalid_argument naming the known ones.
  const PlannerEntry& at(const std::string& name) const;
  /// "pmd, full, pmd-lazy, ..." for messages.
  std::string names() const;

 private:
  std::vector<PlannerEntry> entries_;
};

/// Our planners: pmd, full, pmd-lazy, pmd-connect.
const PlannerRegistry& ourPlanners();

}  // namespace pmdplan
