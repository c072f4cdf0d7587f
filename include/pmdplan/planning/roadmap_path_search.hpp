#pragma once
// FINDPATH's search: A* over the roadmap with the normalised distance to the goal as heuristic
// (consistent, since edge lengths are the same distance).
#include <vector>

#include "pmdplan/planning/roadmap.hpp"

namespace pmdplan {

/// The shortest node sequence from `from` to `to` (both included), or empty if they are not
/// connected. Ties between equal keys are broken by node index, so the result is deterministic.
std::vector<NodeIndex> findRoadmapPath(const Roadmap& roadmap, NodeIndex from, NodeIndex to);

}  // namespace pmdplan
