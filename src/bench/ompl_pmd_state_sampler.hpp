#pragma once
// PMD sampling for any OMPL planner: states of the normalised joint box [0, 1]^n (makeOmplTaskSpace)
// whose hand is drawn from the synergy model as our planner does (SynergyHandSampler: the thumb base
// over its range + every PMD the model has, up to the max-PMDs setting, i.e. the sampler's
// maxDimension; the dimension does not grow, OMPL planners have no per-sample failure signal) and
// whose arm is drawn by ArmSegmentSampler around a point uniform on the start-goal arm segment,
// within a hypercube of half-size rho_a(k) = min(1, rho_a · 2^(k / kDrawsPerDoubling)) after k
// draws (rho_a: PlannerParameters::initialArmHalfSize), so the region grows with the draws as our
// planner's sweeps grow it. Deterministic: our RandomSource is seeded from the sampler's ompl::RNG
// (ompl::RNG::setSeed). sampleUniformNear and sampleGaussian are the uniform space's (clamped to
// the box) around the given state.
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <memory>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

class OmplPmdStateSampler final : public ompl::base::StateSampler {
 public:
  static constexpr double kDrawsPerDoubling = 200.0;

  /// `space` and `hands` are shared with the caller and must outlive the sampler.
  OmplPmdStateSampler(const ompl::base::StateSpace* stateSpace, const PlanningSpace& space,
                      std::shared_ptr<const HandSampler> hands, const Configuration& start, const Configuration& goal,
                      double initialArmHalfSize);

  void sampleUniform(ompl::base::State* state) override;
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;

  /// rho_a of the next draw.
  double armHalfSize() const;

 private:
  const PlanningSpace& space_;
  std::shared_ptr<const HandSampler> hands_;
  ArmSegmentSampler arms_;
  Configuration centre_;  ///< start; its hand entries are overwritten by every draw
  double initialArmHalfSize_;
  RandomSource random_;
  std::size_t draws_ = 0;
  ompl::base::RealVectorStateSampler uniform_;
};

/// Installs the sampler as `stateSpace`'s StateSamplerAllocator (every planner's samplers, valid-state
/// samplers included, then draw from it).
void installPmdStateSampler(ompl::base::StateSpace& stateSpace, const PlanningSpace& space,
                            std::shared_ptr<const HandSampler> hands, const Configuration& start,
                            const Configuration& goal, double initialArmHalfSize);

}  // namespace pmdplan
