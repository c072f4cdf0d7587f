#pragma once
// The settings of the lazy PMD planner (lazy_pmd_planner.hpp) that the paper's planner does not
// have. The ones both share (rho_a, kappa, max-pmds, n_H, time limit, seed, smoothing) stay in
// PlannerSettings; these live there as its `lazy` field, so every front end reaches them
// through planner_setting_table.hpp like every other setting.
#include <cstddef>

namespace pmdplan {

struct LazyPmdSettings {
  /// Arm boxes sampled along the segment per round (at 1/2, 1/4, 3/4, ...), besides the four
  /// at its ends (at c_goal and at c_ini, of the initial and of the round's rho_a), before the
  /// roadmap is searched again. Default 2.
  std::size_t batch = 2;
  /// Most lazy edges from a new node to its nearest nodes (the K of Lazy PRM). Default 10.
  std::size_t neighbours = 10;
  /// Lazy edges join nodes at most this multiple of d(c_ini, c_goal) apart. Default 1 (the
  /// paper's neighbour radius).
  double radius = 1.0;
  /// States inside each edge of a candidate path checked one by one (evenly spaced, midpoint
  /// first) before any edge gets its full motion check: a blocked candidate is most often
  /// rejected by these few state checks instead of by motion checks. 0: none. Default 10.
  std::size_t probes = 10;
  /// rho_a is multiplied by this after every round that found no path, capped at 1. Default 2.
  double armGrowth = 2.0;

  /// Throws InputError (no file; field the setting's key in planner_setting_table.hpp: "lazy-batch",
  /// ...) for values out of range.
  void check() const;
};

}  // namespace pmdplan
