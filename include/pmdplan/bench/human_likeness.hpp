#pragma once
// How human-like a path's hand motion is, the same measure for every planner: how far its hand
// postures are from the synergy subspace the PMD planner samples (the own axes plus its first
// PMDs) and how unusual they are under the synergy model (Mahalanobis distance).
//
// Evaluated along the path, not only at its nodes: the path is walked at a fixed step in the
// normalised joint space (HumanLikenessSettings::step) and every point counts once, so the means
// are arc-length weighted and a long segment through odd postures weighs more than a short one.
// The distance of a straight joint-space segment from the (affine) subspace is convex along the
// segment, so the maximum sits at a node and the walk (which includes the nodes) finds it exactly.
// For a robot with the SAH's hand joints the same walk also measures the distance from the
// authors' PMD subspace, and the path's joint coupling (human_likeness_independent.hpp): measures
// that do not use `model`, so a path is not judged only by the model the PMD planner sampled.
#include <vector>

#include "pmdplan/bench/run_record.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/synergy_hand_sampler.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct HumanLikenessSettings {
  /// Walking step along the path, normalised joint units (all joints): 1 % of a joint's range.
  double step = 0.01;
  /// Directions of the subspace besides the own axes: the PMD planner's largest hand subspace
  /// (SynergySamplingSettings::maxPmds), capped by the model's count.
  int subspaceDirections = SynergySamplingSettings{}.maxPmds;
  /// Directions whose sigma is below this (normalised units) are left out of the Mahalanobis sum:
  /// they carry no variance to divide by.
  double minimumSigma = 1e-9;
};

/// `slots`: for each model joint its configuration index (modelJointSlots in synergy_readout.hpp).
/// A path of one point is measured at that point. Throws std::invalid_argument for an empty path.
HumanLikeness measureHumanLikeness(const std::vector<Configuration>& path, const PlanningSpace& space,
                                   const SynergyModel& model, const std::vector<int>& slots,
                                   const HumanLikenessSettings& options = {});

}  // namespace pmdplan
