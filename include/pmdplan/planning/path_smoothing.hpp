#pragma once
// The smoothing of Sect. 5.3: a small roadmap of the path's nodes with every free straight edge
// between any two of them, and its shortest path from the first node to the last.
#include <cstddef>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

/// Indices (into `path`) of the shortest path over the free edges among the path's nodes. The
/// consecutive edges are taken as free (they are roadmap edges), so the result is never longer
/// than `path`. Edges are checked lazily: the shortest path over edges not yet known to collide is
/// checked, colliding edges are dropped and the search repeated. That returns the same length as
/// checking all n(n-1)/2 edges first, with far fewer motion checks.
std::vector<std::size_t> shortcutPathIndices(const std::vector<Configuration>& path, const PlanningSpace& space,
                                             MotionValidator& motionValidator);

/// The path made of those nodes.
std::vector<Configuration> smoothPath(const std::vector<Configuration>& path, const PlanningSpace& space,
                                      MotionValidator& motionValidator);

/// Sum of the normalised lengths of the path's segments.
double pathLength(const std::vector<Configuration>& path, const PlanningSpace& space);

}  // namespace pmdplan
