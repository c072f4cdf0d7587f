#pragma once
// Where Algorithm 2 (SampleHand) draws hand configurations from. The PMD planner and the
// full-space baseline differ only in the HandSampler they use.
#include <string>

#include "pmdplan/core/sequences/unit_points.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

class HandSampler {
 public:
  virtual ~HandSampler() = default;
  /// Active dimension Algorithm 4 starts every arm configuration with (dimSch = 2 for the paper).
  virtual int initialDimension() const = 0;
  /// Largest active dimension; failed hand samples grow the dimension up to this.
  virtual int maxDimension() const = 0;
  /// Writes the hand entries of `q` (arm entries untouched) with a sample of the box of the first
  /// `dimension` axes; dimension is clamped to [initialDimension, maxDimension]. Takes one point of
  /// that many coordinates from the points' hand stream (whose dimension must be maxDimension).
  virtual void sample(int dimension, UnitPoints& points, Configuration& q) const = 0;
  /// Short name for outputs: "pmd" or "full".
  virtual std::string name() const = 0;
};

}  // namespace pmdplan
