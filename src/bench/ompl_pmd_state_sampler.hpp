#pragma once
// PMD sampling for any OMPL planner: states of the normalised joint box [0, 1]^n (makeOmplTaskSpace)
// whose hand is drawn from the synergy model as our planner does (SynergyHandSampler: the thumb base
// over its range + every PMD the model has, up to the max-PMDs setting, i.e. the sampler's
// maxDimension; the dimension does not grow, OMPL planners have no per-sample failure signal) and
// whose arm is drawn by ArmSegmentSampler around a point uniform on the start-goal arm segment,
// within a hypercube whose half-size is pmd-connect's (arm_box_scales.hpp): log-uniform between
// rho_a and a largest half-size that grows by connect-arm-growth every connect-round draws (OMPL's
// planners do not say when their trees stay apart, so the region grows with the draws). The hand
// point, the segment point and scale and the arm point of a draw come from
// the chosen sequence (PlannerSettings::sequence), seeded from the sampler's ompl::RNG
// (ompl::RNG::setSeed): deterministic. sampleUniformNear and sampleGaussian are the uniform space's (clamped to
// the box) around the given state.
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <memory>

#include "pmdplan/core/sequences/unit_points.hpp"
#include "pmdplan/planning/arm_box_scales.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

class OmplPmdStateSampler final : public ompl::base::StateSampler {
 public:
  /// `space` and `hands` are shared with the caller and must outlive the sampler.
  OmplPmdStateSampler(const ompl::base::StateSpace* stateSpace, const PlanningSpace& space,
                      std::shared_ptr<const HandSampler> hands, const Configuration& start, const Configuration& goal,
                      const PlannerSettings& parameters);

  void sampleUniform(ompl::base::State* state) override;
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;

  /// The arm region's largest half-size at the next draw.
  double largestArmHalfSize() const { return scales_.largest(); }

 private:
  const PlanningSpace& space_;
  std::shared_ptr<const HandSampler> hands_;
  ArmSegmentSampler arms_;
  Configuration centre_;  ///< start; its hand entries are overwritten by every draw
  ArmBoxScales scales_;
  std::size_t roundSamples_;
  UnitPoints points_;
  std::size_t draws_ = 0;
  ompl::base::RealVectorStateSampler uniform_;
};

/// Installs the sampler as `stateSpace`'s StateSamplerAllocator (every planner's samplers, valid-state
/// samplers included, then draw from it).
void installPmdStateSampler(ompl::base::StateSpace& stateSpace, const PlanningSpace& space,
                            std::shared_ptr<const HandSampler> hands, const Configuration& start,
                            const Configuration& goal, const PlannerSettings& parameters);

}  // namespace pmdplan
