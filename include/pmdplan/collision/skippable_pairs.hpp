#pragma once
// Which link pairs may self-collision skip? MoveIt Setup Assistant's reasons: Adjacent (joined by
// a joint, or through links without geometry), Default (in contact at the home pose), Always (in
// contact in every sample) and Never (no sample of the whole joint box brings them into contact).
// Pairs of links on different branches of the tree (finger-finger, thumb-finger) are never skipped
// as Never: rare contacts between fingers are exactly what the hand planner must see.
#include <cstdint>
#include <string>
#include <vector>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct SkippablePairSettings {
  std::size_t samples = 50000;  ///< uniform configurations over the whole joint box
  std::uint64_t seed = 1;
  /// The home (ready) pose: pairs in contact there are skipped as Default, so that the pose is
  /// free. Empty: no Default pairs.
  Configuration home;
};

struct SkippablePair {
  std::string linkA;
  std::string linkB;
  std::string reason;  ///< "Adjacent", "Default", "Always" or "Never" (MoveIt's SRDF vocabulary)
};

/// `model` should be loaded without disabled pairs (groups only) so every pair is tested.
std::vector<SkippablePair> findSkippablePairs(const RobotModel& model, const SkippablePairSettings& params = {});

/// True when the two links hang from different branches below their common ancestor link.
bool onDifferentBranches(const RobotModel& model, int linkA, int linkB);

/// The SRDF-style companion text: the model's groups plus the given disabled pairs. Well-formed
/// XML: `generatedBy` goes into a comment with every "--" spaced apart.
std::string companionFileText(const RobotModel& model, const std::vector<SkippablePair>& pairs,
                              const std::string& generatedBy);
/// The same from groups given by name; `palmLink` empty for no end effector.
std::string companionFileText(const std::string& robotName, const std::vector<RobotModel::GroupDefinition>& groups,
                              const std::string& palmLink, const std::vector<SkippablePair>& pairs,
                              const std::string& generatedBy);

}  // namespace pmdplan
