#pragma once
// What a planner may report while it runs, for a progress display (Planner::setProgressCallback).
// The fields are the paper planner's (Algorithm 4: sweeps over hypercubes); it is the only planner
// that reports, the others accept a callback and never call it.
#include <cstddef>
#include <functional>

#include "pmdplan/planning/search_range.hpp"

namespace pmdplan {

/// A snapshot, given before each hypercube is sampled.
struct PlannerProgress {
  std::size_t sweep = 0;       ///< k of Algorithm 4
  double armHalfSize = 0.0;    ///< rho_a of this sweep
  std::size_t hypercube = 0;   ///< index i in the Van der Corput order, 0 .. hypercubes-1
  std::size_t hypercubes = 0;  ///< STEPS + 1
  SearchRange searchRange;
  std::size_t samples = 0;  ///< hand-arm draws so far
  std::size_t roadmapNodes = 0;
  std::size_t components = 0;
  double elapsedSeconds = 0.0;
};

/// Must not touch the planner; it only observes.
using ProgressCallback = std::function<void(const PlannerProgress&)>;

}  // namespace pmdplan
