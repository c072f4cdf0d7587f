#include "ompl_pmd_state_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_checker_adapters.hpp"

namespace pmdplan {

namespace ob = ompl::base;

OmplPmdStateSampler::OmplPmdStateSampler(const ob::StateSpace* stateSpace, const PlanningSpace& space,
                                         std::shared_ptr<const HandSampler> hands, const Configuration& start,
                                         const Configuration& goal, double initialArmHalfSize)
    : ob::StateSampler(stateSpace),
      space_(space),
      hands_(std::move(hands)),
      arms_(space, start, goal),
      centre_(start),
      initialArmHalfSize_(initialArmHalfSize),
      random_(static_cast<std::uint64_t>(rng_.uniformInt(1, std::numeric_limits<int>::max()))),
      uniform_(stateSpace) {}

double OmplPmdStateSampler::armHalfSize() const {
  return std::min(1.0, initialArmHalfSize_ * std::exp2(static_cast<double>(draws_) / kDrawsPerDoubling));
}

void OmplPmdStateSampler::sampleUniform(ob::State* state) {
  Configuration q = centre_;
  hands_->sample(hands_->maxDimension(), random_, q);
  arms_.draw(random_.uniform01(), armHalfSize(), random_, q);
  ++draws_;
  setStateFromConfiguration(space_, q, state);
}

void OmplPmdStateSampler::sampleUniformNear(ob::State* state, const ob::State* near, double distance) {
  uniform_.sampleUniformNear(state, near, distance);
}

void OmplPmdStateSampler::sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) {
  uniform_.sampleGaussian(state, mean, stdDev);
}

void installPmdStateSampler(ob::StateSpace& stateSpace, const PlanningSpace& space,
                            std::shared_ptr<const HandSampler> hands, const Configuration& start,
                            const Configuration& goal, double initialArmHalfSize) {
  stateSpace.setStateSamplerAllocator([&space, hands, start, goal, initialArmHalfSize](const ob::StateSpace* s) {
    return std::make_shared<OmplPmdStateSampler>(s, space, hands, start, goal, initialArmHalfSize);
  });
}

}  // namespace pmdplan
