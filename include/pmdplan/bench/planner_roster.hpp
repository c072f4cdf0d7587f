#pragma once
// Every planner the front ends know, by the names they take: ours (planning/planner_registry.hpp:
// pmd, full, pmd-lazy, pmd-connect) and OMPL's geometric planners (ompl_planner.hpp:
// ompl:RRTConnect, ..., each also with PMD sampling, ompl:RRTConnect@pmd, ...), all planning on the
// same checks through the one service (planning/task_planning.hpp). The registry of this layer,
// because OMPL is linked here.
#include <string>

#include "pmdplan/planning/planner_registry.hpp"

namespace pmdplan {

/// Ours, then OMPL's, then OMPL's with PMD sampling: the order help and error messages list them.
const PlannerRegistry& plannerRoster();
/// The entry of a name, or nullptr.
const PlannerEntry* findPlanner(const std::string& name);
/// "pmd, full, pmd-lazy, pmd-connect, ompl:RRTConnect, ..." for messages.
std::string knownPlannerNames();
/// The entry of a name, or InputError (no file, the given field: "--planner" on the command line,
/// "planner" in Python) naming the known planners.
const PlannerEntry& plannerNamed(const std::string& name, const std::string& field);

}  // namespace pmdplan
