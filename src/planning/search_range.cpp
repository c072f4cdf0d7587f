#include "pmdplan/planning/search_range.hpp"

#include <algorithm>

namespace pmdplan {

SearchRange updateSearchRange(const Roadmap& roadmap, NodeIndex start, NodeIndex goal) {
  double dIni = roadmap.node(start).step;
  double dGoal = roadmap.node(goal).step;
  for (NodeIndex i = 0; i < roadmap.nodeCount(); ++i) {
    const double step = roadmap.node(i).step;
    if (roadmap.sameComponent(i, start)) dIni = std::max(dIni, step);
    if (roadmap.sameComponent(i, goal)) dGoal = std::min(dGoal, step);
  }
  if (dIni > dGoal) std::swap(dIni, dGoal);
  return {dIni, dGoal};
}

}  // namespace pmdplan
