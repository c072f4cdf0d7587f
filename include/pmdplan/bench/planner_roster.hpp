#pragma once
// The planners `pmdplan bench` can compare, by the names the command line uses: ours (pmd, full, pmd-lazy)
// and OMPL's geometric planners (ompl:RRTConnect, ...), all on the same checks.
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/task_planning.hpp"

namespace pmdplan {

enum class PlannerFamily {
  PmdRoadmap,  ///< our planner, with the hand sampling mode of the entry
  Ompl,        ///< an OMPL geometric planner in the normalised 19-D joint box
};

struct PlannerEntry {
  std::string name;  ///< as on the command line: "pmd", "ompl:RRTConnect"
  PlannerFamily family = PlannerFamily::PmdRoadmap;
  HandSamplingMode mode = HandSamplingMode::Synergy;  ///< PmdRoadmap only
  std::string omplName;                               ///< Ompl only: "RRTConnect" (ompl_planning.hpp makes it)
  std::string description;
  /// Ompl only: states drawn by PMD sampling (name "ompl:<Planner>@pmd").
  bool pmdSampling = false;
  /// PmdRoadmap only: the paper's roadmap or the lazy one.
  RoadmapAlgorithm algorithm = RoadmapAlgorithm::Paper;
};

/// Every known planner, in the order the help and error messages list them.
const std::vector<PlannerEntry>& plannerRoster();
/// The entry of a name, or nothing.
std::optional<PlannerEntry> findPlanner(const std::string& name);
/// "pmd, full, ompl:RRTConnect, ..." for messages.
std::string knownPlannerNames();

}  // namespace pmdplan
