#include "pmdplan/planning/search_range.hpp"

#include <algorithm>

namespace pmdplan {

SearchRange updateSearchRange(const Roadmap& roadmap, NodeIndex start, NodeIndex goal) {
  double dIni = roadmap.largestStep(start);
  double dGoal = roadmap.smallestStep(goal);
  if (dIni > dGoal) std::swap(dIni, dGoal);
  return {dIni, dGoal};
}

}  // namespace pmdplan
