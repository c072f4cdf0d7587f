#include "pmdplan/planning/planner_registry.hpp"

#include <stdexcept>
#include <utility>

#include "pmdplan/planning/lazy_pmd_planner.hpp"
#include "pmdplan/planning/pmd_connect_planner.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"

namespace pmdplan {
namespace {

/// The registry line of one of our planners: a PmdPlannerBase with the hand sampler of `mode`.
template <typename OurPlanner>
PlannerEntry ours(std::string name, HandSamplingMode mode, std::string description) {
  PlannerEntry entry;
  entry.name = std::move(name);
  entry.description = std::move(description);
  entry.allocate = [mode](const PlannerContext& c) -> std::unique_ptr<Planner> {
    return std::make_unique<OurPlanner>(c.space, c.states, c.motions,
                                        makeHandSampler(mode, c.space, c.synergies, c.settings.pmdBox), c.settings);
  };
  entry.mode = mode;
  entry.usesSynergies = mode == HandSamplingMode::Synergy;
  entry.family = PlannerFamily::PmdRoadmap;
  return entry;
}

}  // namespace

const PlannerRegistry& ourPlanners() {
  static const PlannerRegistry registry({
      ours<PmdRoadmapPlanner>("pmd", HandSamplingMode::Synergy, "the paper's planner, hands from the PMD subspace"),
      ours<PmdRoadmapPlanner>("full", HandSamplingMode::FullSpace, "the same roadmap, hands over the whole joint box"),
      ours<LazyPmdPlanner>("pmd-lazy", HandSamplingMode::Synergy,
                           "our lazy PMD roadmap: PMD samples, edges checked only on candidate paths"),
      ours<PmdConnectPlanner>("pmd-connect", HandSamplingMode::Synergy,
                              "our bidirectional PMD trees: RRT-Connect grown with PMD samples near the segment"),
  });
  return registry;
}

PlannerRegistry::PlannerRegistry(std::vector<PlannerEntry> entries) : entries_(std::move(entries)) {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (!entries_[i].allocate) throw std::invalid_argument("planner '" + entries_[i].name + "' has no allocator");
    for (std::size_t j = 0; j < i; ++j)
      if (entries_[j].name == entries_[i].name)
        throw std::invalid_argument("planner '" + entries_[i].name + "' is registered twice");
  }
}

const PlannerEntry* PlannerRegistry::find(const std::string& name) const {
  for (const PlannerEntry& entry : entries_)
    if (entry.name == name) return &entry;
  return nullptr;
}

const PlannerEntry& PlannerRegistry::at(const std::string& name) const {
  if (const PlannerEntry* entry = find(name)) return *entry;
  throw std::invalid_argument("'" + name + "' is not a planner; known planners: " + names());
}

std::string PlannerRegistry::names() const {
  std::string names;
  for (const PlannerEntry& entry : entries_) names += (names.empty() ? "" : ", ") + entry.name;
  return names;
}

}  // namespace pmdplan
