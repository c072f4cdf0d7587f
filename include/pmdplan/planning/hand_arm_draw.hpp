#pragma once
// The hand-arm sampling of the three PMD planners for one arm hypercube B^a(step): up to n_A arm
// configurations (Algorithm 1, one trial each), each with up to n_H hand configurations
// (Algorithm 2, one trial each), the hand dimension growing by one per failed hand sample. A
// sample is one hand-arm draw (Table 2's count); N bounds the samples and, so that an arm that never
// comes free cannot loop for ever, the arm trials too. N and the time limit are checked before
// every draw.
#include <optional>

#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/core/sequences/unit_points.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner_run.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

/// What the planner samples with (all borrowed for one call).
struct HandArmSources {
  const PlanningSpace& space;
  const ArmSegmentSampler& arm;
  const HandSampler& hand;
  StateValidator& validator;
  const PlannerSettings& parameters;
};

/// A free hand-arm sample with the hand dimension it was drawn at, nothing, or a reason to stop.
struct HandArmDraw {
  std::optional<Configuration> sample;
  int handDimension = 0;
  std::optional<PlannerStatus> stop;
};

/// `q` starts as c_ini (a hand alone keeps its arm-less entries); counts go to `statistics`
/// (samples, arm trials, state checks, max trials, nodes by hand dimension).
HandArmDraw drawHandArm(const HandArmSources& sources, double step, double armHalfSize, Configuration q,
                        UnitPoints& points, const PlannerRun& run, PlanningStatistics& statistics);

}  // namespace pmdplan
