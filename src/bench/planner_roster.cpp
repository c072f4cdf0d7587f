#include "pmdplan/bench/planner_roster.hpp"

#include <vector>

#include "pmdplan/bench/ompl_planner.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

const PlannerRegistry& plannerRoster() {
  static const PlannerRegistry roster = [] {
    std::vector<PlannerEntry> entries = ourPlanners().entries();
    for (PlannerEntry& entry : omplPlannerEntries()) entries.push_back(std::move(entry));
    return PlannerRegistry(std::move(entries));
  }();
  return roster;
}

const PlannerEntry* findPlanner(const std::string& name) { return plannerRoster().find(name); }

std::string knownPlannerNames() { return plannerRoster().names(); }

const PlannerEntry& plannerNamed(const std::string& name, const std::string& field) {
  if (const PlannerEntry* entry = findPlanner(name)) return *entry;
  throw InputError("", field, "'" + name + "' is not a planner; known planners: " + knownPlannerNames());
}

}  // namespace pmdplan
