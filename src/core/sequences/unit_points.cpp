#include "pmdplan/core/sequences/unit_points.hpp"

#include <stdexcept>
#include <string>

#include "pmdplan/core/sequences/halton_sequence.hpp"
#include "pmdplan/core/sequences/sdk_sequence.hpp"

namespace pmdplan {

UnitPoints::UnitPoints(SampleSequence sequence, std::uint64_t seed, PointStreamDimensions dimensions) {
  reset(sequence, seed, dimensions);
}

void UnitPoints::reset(SampleSequence sequence, std::uint64_t seed, PointStreamDimensions dimensions) {
  if (dimensions.hand < 0 || dimensions.arm < 0 || dimensions.segmentPoint < 0)
    throw std::invalid_argument("UnitPoints: a stream dimension is negative");
  sequence_ = sequence;
  dimensions_ = dimensions;
  random_.reseed(seed);
  const std::array<int, 3> sizes = {dimensions.hand, dimensions.arm, dimensions.segmentPoint};
  int firstBase = 0;
  for (std::size_t s = 0; s < streams_.size(); ++s) {
    streams_[s].reset();
    if (sizes[s] == 0 || sequence == SampleSequence::Random) continue;
    if (sequence == SampleSequence::Halton)
      streams_[s] = std::make_unique<HaltonSequence>(firstBase, sizes[s], random_);
    else
      streams_[s] = std::make_unique<SdkSequence>(sizes[s], random_);
    firstBase += sizes[s];
  }
}

void UnitPoints::next(PointStream stream, int dimension, double* point) {
  const auto s = static_cast<std::size_t>(stream);
  const std::array<int, 3> sizes = {dimensions_.hand, dimensions_.arm, dimensions_.segmentPoint};
  if (dimension < 0 || dimension > sizes[s])
    throw std::invalid_argument("UnitPoints::next: " + std::to_string(dimension) +
                                " coordinates asked of a stream of " + std::to_string(sizes[s]));
  if (dimension == 0) return;
  if (sequence_ == SampleSequence::Random) {
    for (int i = 0; i < dimension; ++i) point[i] = random_.uniform01();
    return;
  }
  streams_[s]->next(dimension, point);
}

}  // namespace pmdplan
