#include "pmdplan/planning/hand_arm_draw.hpp"

#include <algorithm>
#include <cstddef>

namespace pmdplan {

HandArmDraw drawHandArm(const HandArmSources& sources, double step, double armHalfSize, Configuration q,
                        UnitPoints& points, const PlannerRun& run, PlanningStatistics& statistics) {
  const PlannerSettings& parameters = sources.parameters;
  std::size_t trials = 0;
  for (int j = 0; j < parameters.armTrials; ++j) {
    if (statistics.samples >= parameters.maxSamples || statistics.armTrials >= parameters.maxSamples)
      return {std::nullopt, 0, PlannerStatus::SampleLimit};
    if (run.timeIsUp()) return {std::nullopt, 0, PlannerStatus::TimeLimit};
    ++statistics.armTrials;
    // A hand alone has no arm to sample (its segment has length 0: the hypercubes at 0 and 1
    // only, which try c_ini and c_goal in turn).
    if (!sources.space.armIndices.empty()) {
      ++statistics.stateChecks;
      if (!sources.arm.sample(step, armHalfSize, points, sources.validator, q)) continue;
    }
    int dimSch = sources.hand.initialDimension();
    for (int h = 0; h < parameters.handTrials; ++h) {
      if (statistics.samples >= parameters.maxSamples) return {std::nullopt, 0, PlannerStatus::SampleLimit};
      if (run.timeIsUp()) return {std::nullopt, 0, PlannerStatus::TimeLimit};
      sources.hand.sample(dimSch, points, q);
      ++statistics.samples;
      ++statistics.stateChecks;
      ++trials;
      if (sources.validator.isValid(q)) {
        statistics.maxTrials = std::max(statistics.maxTrials, trials);
        ++statistics.nodesByHandDimension[dimSch];
        return {std::move(q), dimSch, std::nullopt};
      }
      dimSch = std::min(dimSch + 1, sources.hand.maxDimension());
    }
  }
  return {};
}

}  // namespace pmdplan
