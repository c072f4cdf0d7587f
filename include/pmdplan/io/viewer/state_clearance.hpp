#pragma once
// For each state of a path the viewer shows, judged by the grasp rule (collision/grasp_rule.hpp)
// in the state's phase: the links in a pair that counts (a collision: drawn red), the links in
// allowed grasp contact (a hand link touching the target while the hand closes: drawn as allowed
// contact), and the robot's smallest distance over the link-obstacle pairs that count (its
// clearance: while closing, from the other obstacles, and the arm's from the target too). Links
// that no joint moves (the robot's base, fixed to the world and usually standing on the floor)
// are left out of the clearance: their distance is the same in every state.
#include <string>
#include <vector>

#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct StateClearance {
  /// Metres; in contact that counts, minus the penetration depth (0 where the depth cannot be told
  /// apart from allowed grasp contact: an arm link in the target while the hand closes).
  double clearance = 0.0;
  std::vector<std::string> collidingLinks;  ///< robot links in a colliding pair that counts, each once
  std::vector<std::string> contactLinks;    ///< robot links in allowed grasp contact, each once
};

/// `phases` index `states`: the closing phase from state `phases.closingFrom` on.
std::vector<StateClearance> stateClearances(const Task& task, const std::vector<Configuration>& states,
                                            const PathPhases& phases = {});

}  // namespace pmdplan
