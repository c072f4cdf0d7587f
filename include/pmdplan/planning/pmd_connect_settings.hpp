#pragma once
// The settings of the bidirectional PMD planner (pmd_connect_planner.hpp) that the other PMD
// planners do not have. Shared ones (rho_a, n_A, n_H, kappa, max-pmds, N, time limit, seed,
// sequence, smoothing) stay in PlannerSettings; these live there as its `connect` field, so
// every front end reaches them through planner_setting_table.hpp like every other setting. The
// defaults were chosen by measurement on the built-in tasks (docs/planners.md).
#include <cstddef>

namespace pmdplan {

struct PmdConnectSettings {
  /// Longest step a tree takes toward a sample, as a multiple of d(c_ini, c_goal) in the
  /// normalised joint space (RRT-Connect's range); inf: no limit. Our motion check costs little
  /// more for a long free segment than for a short one, so long steps pay. Default 1.
  double range = 1.0;
  /// Samples drawn per round; the arm region grows after each round that did not join the trees.
  /// Default 2.
  std::size_t round = 2;
  /// The arm region's largest half-size starts at rho_a and is multiplied by this after every round
  /// that did not join the trees, capped at 1 (the whole arm box). Default 8.
  double armGrowth = 8.0;
  /// Inner states of a new tree segment checked (the first in Van der Corput order: midpoint,
  /// quarters, ...; together, so the fast checker takes them in one batch) before the segment joins
  /// its tree; its full motion check waits until it lies on a path joining c_ini and c_goal (lazy,
  /// as in Bohlin & Kavraki's Lazy PRM). 0: none. Default 4.
  std::size_t probes = 4;

  /// Throws InputError (no file; field the setting's key in planner_setting_table.hpp: "connect-range",
  /// ...) for values out of range.
  void check() const;
};

}  // namespace pmdplan
