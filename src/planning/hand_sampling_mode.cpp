#include "pmdplan/planning/hand_sampling_mode.hpp"

#include <stdexcept>

#include "pmdplan/planning/full_space_hand_sampler.hpp"

namespace pmdplan {

std::string handSamplingModeName(HandSamplingMode mode) { return mode == HandSamplingMode::Synergy ? "pmd" : "full"; }

std::optional<HandSamplingMode> parseHandSamplingMode(const std::string& name) {
  if (name == "pmd") return HandSamplingMode::Synergy;
  if (name == "full") return HandSamplingMode::FullSpace;
  return std::nullopt;
}

std::unique_ptr<HandSampler> makeHandSampler(HandSamplingMode mode, const PlanningSpace& space,
                                             const SynergyModel* model, const SynergySamplingSettings& parameters) {
  if (mode == HandSamplingMode::FullSpace) return std::make_unique<FullSpaceHandSampler>(space);
  if (model == nullptr) throw std::invalid_argument("makeHandSampler: the PMD planner needs a synergy model");
  return std::make_unique<SynergyHandSampler>(space, *model, parameters);
}

}  // namespace pmdplan
