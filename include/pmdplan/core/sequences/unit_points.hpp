#pragma once
// One run's points: a stream per consumer — the hand sampler, the arm sampler, and the point on the
// start-goal segment that the OMPL PMD sampler draws — each its own sequence of the chosen kind, all
// seeded from the run's seed. With SampleSequence::Random the streams are the one RandomSource,
// read in the order the consumers ask, as if they drew from it directly. The Halton streams take
// disjoint prime bases (hand first, then arm, then segment point), so draws made in step (the OMPL
// sampler's) form one Halton sequence of their joint dimension.
#include <array>
#include <cstdint>
#include <memory>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/core/sequences/sample_sequence.hpp"

namespace pmdplan {

enum class PointStream { Hand, Arm, SegmentPoint };

/// The most coordinates each stream draws at once.
struct PointStreamDimensions {
  int hand = 0;
  int arm = 0;
  int segmentPoint = 1;
};

class UnitPoints {
 public:
  /// Random, seed 1, no streams yet (reset before use).
  UnitPoints() = default;
  UnitPoints(SampleSequence sequence, std::uint64_t seed, PointStreamDimensions dimensions);

  /// Starts the streams again from `seed`. Throws std::invalid_argument for a negative dimension.
  void reset(SampleSequence sequence, std::uint64_t seed, PointStreamDimensions dimensions);

  /// The stream's next point, `dimension` coordinates in [0, 1) (std::invalid_argument past the
  /// stream's dimension).
  void next(PointStream stream, int dimension, double* point);

  SampleSequence sequence() const { return sequence_; }

 private:
  SampleSequence sequence_ = SampleSequence::Random;
  PointStreamDimensions dimensions_;
  RandomSource random_;
  std::array<std::unique_ptr<UnitSequence>, 3> streams_;
};

}  // namespace pmdplan
