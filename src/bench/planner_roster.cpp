#include "pmdplan/bench/planner_roster.hpp"

namespace pmdplan {

const std::vector<PlannerEntry>& plannerRoster() {
  static const std::vector<PlannerEntry> roster = [] {
    std::vector<PlannerEntry> entries = {
        {"pmd", PlannerFamily::PmdRoadmap, HandSamplingMode::Synergy, "",
         "the paper's planner, hands from the PMD subspace"},
        {"full", PlannerFamily::PmdRoadmap, HandSamplingMode::FullSpace, "",
         "the same roadmap, hands over the whole joint box"},
        {"pmd-lazy", PlannerFamily::PmdRoadmap, HandSamplingMode::Synergy, "",
         "our lazy PMD roadmap: PMD samples, edges checked only on candidate paths", false, RoadmapAlgorithm::Lazy},
        {"pmd-connect", PlannerFamily::PmdRoadmap, HandSamplingMode::Synergy, "",
         "our bidirectional PMD trees: RRT-Connect grown with PMD samples near the segment", false,
         RoadmapAlgorithm::Connect},
        {"ompl:RRTConnect", PlannerFamily::Ompl, HandSamplingMode::Synergy, "RRTConnect", "OMPL bidirectional RRT"},
        {"ompl:PRM", PlannerFamily::Ompl, HandSamplingMode::Synergy, "PRM", "OMPL probabilistic roadmap"},
        {"ompl:LazyPRM", PlannerFamily::Ompl, HandSamplingMode::Synergy, "LazyPRM", "OMPL PRM with lazy edge checks"},
        {"ompl:KPIECE1", PlannerFamily::Ompl, HandSamplingMode::Synergy, "KPIECE1", "OMPL KPIECE"},
        {"ompl:BKPIECE1", PlannerFamily::Ompl, HandSamplingMode::Synergy, "BKPIECE1", "OMPL bidirectional KPIECE"},
        {"ompl:EST", PlannerFamily::Ompl, HandSamplingMode::Synergy, "EST", "OMPL expansive space trees"},
        {"ompl:RRT", PlannerFamily::Ompl, HandSamplingMode::Synergy, "RRT", "OMPL RRT"},
    };
    const std::size_t count = entries.size();
    for (std::size_t i = 0; i < count; ++i) {
      if (entries[i].family != PlannerFamily::Ompl) continue;
      PlannerEntry pmd = entries[i];
      pmd.name += "@pmd";
      pmd.description += ", states from PMD sampling";
      pmd.pmdSampling = true;
      entries.push_back(pmd);
    }
    return entries;
  }();
  return roster;
}

std::optional<PlannerEntry> findPlanner(const std::string& name) {
  for (const auto& entry : plannerRoster())
    if (entry.name == name) return entry;
  return std::nullopt;
}

std::string knownPlannerNames() {
  std::string names;
  for (const auto& entry : plannerRoster()) names += (names.empty() ? "" : ", ") + entry.name;
  return names;
}

}  // namespace pmdplan
