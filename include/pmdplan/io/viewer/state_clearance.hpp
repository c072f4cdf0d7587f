#pragma once
// For each state of a path the viewer shows: the exact checker's colliding pairs (the links to
// draw red) and the robot's smallest distance to the task's obstacles (its clearance). Links that no
// joint moves (the robot's base, fixed to the world and usually standing on the floor) are left
// out of the clearance: their distance is the same in every state.
#include <string>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct StateClearance {
  double clearance = 0.0;                   ///< metres; 0 or less in contact
  std::vector<std::string> collidingLinks;  ///< robot links in a colliding pair, each once
};

std::vector<StateClearance> stateClearances(const Task& task, const std::vector<Configuration>& states);

}  // namespace pmdplan
