#pragma once
// The one switch between the PMD planner and its full-space baseline (`--planner pmd|full`).
#include <memory>
#include <optional>
#include <string>

#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/synergy_hand_sampler.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

enum class HandSamplingMode {
  Synergy,    ///< "pmd": the paper's planner, hands from the PMD subspace
  FullSpace,  ///< "full": hands uniform over the whole hand joint box
};

/// "pmd" / "full".
std::string handSamplingModeName(HandSamplingMode mode);
/// Inverse of handSamplingModeName; std::nullopt for anything else.
std::optional<HandSamplingMode> parseHandSamplingMode(const std::string& name);

/// The hand sampler of a mode. Synergy needs `model` (std::invalid_argument if null); FullSpace
/// ignores it.
std::unique_ptr<HandSampler> makeHandSampler(HandSamplingMode mode, const PlanningSpace& space,
                                             const SynergyModel* model, const SynergySamplingSettings& parameters = {});

}  // namespace pmdplan
