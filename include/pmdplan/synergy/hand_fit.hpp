#pragma once
// Whether a synergy model fits a robot hand: it covers exactly the hand's joints, each once with
// finite limits, and its mean, directions, sigma and own-axis joints agree in size and kind. The
// planner's sampler checks it, and `pmdplan plan` before planning, naming the model's file.
#include <string>
#include <vector>

#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// Throws InputError naming `modelFile` (may be empty) and the field ("joints", "mean",
/// "directions", "sigma" or "own_axis_joints") of the first thing that does not fit the hand whose
/// joints are `handJoints`.
void checkSynergyModelFitsHand(const SynergyModel& model, const std::vector<std::string>& handJoints,
                               const std::string& modelFile);

}  // namespace pmdplan
