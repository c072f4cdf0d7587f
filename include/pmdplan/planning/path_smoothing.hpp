#pragma once
// The smoothing of Sect. 5.3: a small roadmap of the path's nodes with every free straight edge
// between any two of them, and its shortest path from the first node to the last.
#include <cstddef>
#include <functional>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

/// The most path nodes smoothed together (their tables take 9 bytes per pair: 9 MB).
inline constexpr std::size_t kMaxSmoothingWindowNodes = 1000;

/// Indices (into `path`) of the shortest path over the free edges among the path's nodes. The
/// consecutive edges are taken as free (they are roadmap edges), so the result is never longer
/// than `path`. Edges are checked lazily: the shortest path over edges not yet known to collide is
/// checked, colliding edges are dropped and the search repeated. That returns the same length as
/// checking all n(n-1)/2 edges first, with far fewer motion checks.
///
/// Bounded work: a path of more than kMaxSmoothingWindowNodes nodes is smoothed in windows of that
/// many consecutive nodes (its n x n tables would otherwise grow with the square of a path that a
/// tiny step made long); once `stop` says so (the run's deadline or the caller's stop request),
/// edges not yet checked count as blocked, so the answer comes at once and is still free.
std::vector<std::size_t> shortcutPathIndices(const std::vector<Configuration>& path, const PlanningSpace& space,
                                             MotionValidator& motionValidator, const std::function<bool()>& stop = {});

/// The path made of those nodes.
std::vector<Configuration> smoothPath(const std::vector<Configuration>& path, const PlanningSpace& space,
                                      MotionValidator& motionValidator, const std::function<bool()>& stop = {});

/// Sum of the normalised lengths of the path's segments.
double pathLength(const std::vector<Configuration>& path, const PlanningSpace& space);

}  // namespace pmdplan
