#pragma once
// Which link pairs may self-collision skip? Adjacent links (joined by a joint, or through links
// without geometry), and pairs that sampling the whole joint box never brings into contact. Pairs
// of links on different branches of the tree (finger-finger, thumb-finger) are never skipped:
// rare contacts between fingers are exactly what the hand planner must see.
#include <cstdint>
#include <string>
#include <vector>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct SkippablePairParams {
  std::size_t samples = 50000;  ///< uniform configurations over the whole joint box
  std::uint64_t seed = 1;
};

struct SkippablePair {
  std::string linkA;
  std::string linkB;
  std::string reason;  ///< "Adjacent" or "Never" (MoveIt's SRDF vocabulary)
};

/// `model` should be loaded without disabled pairs (groups only) so every pair is tested.
std::vector<SkippablePair> findSkippablePairs(const RobotModel& model, const SkippablePairParams& params = {});

/// True when the two links hang from different branches below their common ancestor link.
bool onDifferentBranches(const RobotModel& model, int linkA, int linkB);

/// The SRDF-style companion text: the model's groups plus the given disabled pairs.
std::string companionFileText(const RobotModel& model, const std::vector<SkippablePair>& pairs, const std::string& generatedBy);

}  // namespace pmdplan
