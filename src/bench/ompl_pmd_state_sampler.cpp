#include "ompl_pmd_state_sampler.hpp"

#include <algorithm>
#include <limits>

#include "ompl_checker_adapters.hpp"

namespace pmdplan {

namespace ob = ompl::base;

OmplPmdStateSampler::OmplPmdStateSampler(const ob::StateSpace* stateSpace, const PlanningSpace& space,
                                         std::shared_ptr<const HandSampler> hands, const Configuration& start,
                                         const Configuration& goal, const PlannerSettings& parameters)
    : ob::StateSampler(stateSpace),
      space_(space),
      hands_(std::move(hands)),
      arms_(space, start, goal),
      centre_(start),
      scales_(parameters.rhoA, parameters.connect.armGrowth),
      roundSamples_(parameters.connect.round),
      points_(parameters.sequence, static_cast<std::uint64_t>(rng_.uniformInt(1, std::numeric_limits<int>::max())),
              {hands_->maxDimension(), arms_.dimension(), 2}),
      uniform_(stateSpace) {}

void OmplPmdStateSampler::sampleUniform(ob::State* state) {
  Configuration q = centre_;
  hands_->sample(hands_->maxDimension(), points_, q);
  double point[2];  // where on the segment, and the box's scale
  points_.next(PointStream::SegmentPoint, 2, point);
  arms_.draw(point[0], scales_.halfSize(point[1]), points_, q);
  if (++draws_ % roundSamples_ == 0) scales_.grow();
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
                            const Configuration& goal, const PlannerSettings& parameters) {
  stateSpace.setStateSamplerAllocator([&space, hands, start, goal, parameters](const ob::StateSpace* s) {
    return std::make_shared<OmplPmdStateSampler>(s, space, hands, start, goal, parameters);
  });
}

}  // namespace pmdplan
