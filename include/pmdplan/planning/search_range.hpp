#pragma once
// The search range [d_ini, d_goal] of Sect. 5.3 / Fig. 13: only hypercubes centred between the
// farthest sample joined to c_ini and the nearest sample joined to c_goal can help join the two.
#include "pmdplan/planning/roadmap.hpp"

namespace pmdplan {

struct SearchRange {
  double low = 0.0;   ///< d_ini
  double high = 1.0;  ///< d_goal
  bool contains(double step) const { return step >= low && step <= high; }
};

/// UPDATESEARCHRANGE from the whole roadmap: d_ini = largest step of a node in c_ini's component,
/// d_goal = smallest step of a node in c_goal's component (their own steps are 0 and 1). If the
/// components reach past each other (d_ini > d_goal) the gap lies somewhere in between, so the
/// range is [d_goal, d_ini] rather than empty.
SearchRange updateSearchRange(const Roadmap& roadmap, NodeIndex start, NodeIndex goal);

}  // namespace pmdplan
